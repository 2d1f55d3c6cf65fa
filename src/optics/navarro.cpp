// Navarro accommodation (see navarro.h for the formulas and the retina choice).
#include "optics/navarro.h"

#include <cmath>

#include <fmt/format.h>

#include "optics/optics_error.h"

namespace eyetrace::optics {

namespace {

int find_surface(const Prescription& p, const char* name) {
  for (size_t i = 0; i < p.surfaces.size(); ++i)
    if (p.surfaces[i].name == name) return static_cast<int>(i);
  throw OpticsError(fmt::format("navarro accommodation: prescription '{}' has no surface '{}'", p.name, name));
}

}  // namespace

double navarro_lens_index_shift(double D, NavarroLensIndexLaw law) {
  return law == NavarroLensIndexLaw::Navarro1985 ? 9e-5 * (10.0 * D + D * D) : 9e-5 * std::log(D + 1.0);
}

Prescription navarro_accommodate(const Prescription& base, double D, NavarroLensIndexLaw law) {
  if (!(D >= 0.0 && D <= kNavarroMax_D))
    throw OpticsError(
        fmt::format("accommodation: {} D is outside the Navarro model's range [0, {}] D", D, kNavarroMax_D));
  Prescription p = base;
  const int cornea_back = find_surface(p, "cornea posterior");
  const int pupil = find_surface(p, "pupil");
  const int lens_front = find_surface(p, "lens anterior");
  const int lens_back = find_surface(p, "lens posterior");
  const double axial_length = p.axial_length_mm();
  const double l = std::log(D + 1.0);

  // Aqueous depth runs from the posterior cornea to the anterior lens, with the pupil in
  // between (at the lens vertex in the presets): keep the pupil-to-lens distance.
  const double pupil_to_lens = p.vertex_z_mm()[lens_front] - p.vertex_z_mm()[pupil];
  p.surfaces[cornea_back].thickness_mm = (3.05 - 0.05 * l) - pupil_to_lens;
  p.surfaces[lens_front].profile = SurfaceProfile::from_radius(10.2 - 1.75 * l, -3.1316 - 0.34 * l);
  p.surfaces[lens_front].thickness_mm = 4.0 + 0.1 * l;
  p.surfaces[lens_back].profile = SurfaceProfile::from_radius(-6.0 + 0.2294 * l, -1.0 - 0.125 * l);
  p.surfaces[lens_back].thickness_mm = 0.0;
  p.surfaces[lens_back].thickness_mm = axial_length - p.axial_length_mm();  // fixed axial length

  const double shift = navarro_lens_index_shift(D, law);
  bool found = false;
  for (Medium& m : p.media)
    if (m.name == "lens") {
      m.index += shift;
      found = true;
    }
  if (!found) throw OpticsError(fmt::format("navarro accommodation: prescription '{}' has no medium 'lens'", p.name));
  for (Surface& s : p.surfaces)
    if (s.medium == "lens") s.index_after = p.find_medium("lens")->index_at(p.wavelength_nm);
  if (D > kNavarroMaxPublished_D)
    p.notes.push_back(
        fmt::format("accommodation D = {} is beyond the 0-10 D range Navarro et al. "
                    "fitted: extrapolated",
                    D));
  return p;
}

}  // namespace eyetrace::optics
