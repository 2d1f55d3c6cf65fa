// The accommodation laws the eye data files name. Each is a pure function of the model's
// relaxed (and, for interpolating laws, accommodated) prescription and A; the formulas and
// their sources are in shared/optics/eye-models.md and docs/eye-models.md.
#include "optics/accommodation_laws.h"

#include <algorithm>

#include <fmt/format.h>

#include "optics/eye_model.h"
#include "optics/navarro.h"
#include "optics/optics_error.h"
#include "optics/paraxial.h"

namespace eyetrace::optics {

namespace {

// Linear interpolation of two states of one eye with the same surfaces: curvature, conic,
// thickness and indices (media by name). f = 0 gives a, f = 1 gives b.
Prescription interpolate(const Prescription& a, const Prescription& b, double f) {
  Prescription p = a;
  auto lerp = [f](double x, double y) { return x + f * (y - x); };
  for (size_t i = 0; i < p.surfaces.size(); ++i) {
    Surface& s = p.surfaces[i];
    const Surface& t = b.surfaces[i];
    s.profile =
        SurfaceProfile::from_curvature(lerp(a.surfaces[i].profile.is_flat() ? 0.0 : a.surfaces[i].profile.curvature,
                                            t.profile.is_flat() ? 0.0 : t.profile.curvature),
                                       lerp(s.profile.conic, t.profile.conic));
    s.thickness_mm = lerp(s.thickness_mm, t.thickness_mm);
    s.index_after = lerp(s.index_after, t.index_after);
  }
  for (Medium& m : p.media)
    if (const Medium* mb = b.find_medium(m.name)) m.index = lerp(m.index, mb->index);
  return p;
}

// --- none: a model published relaxed only -------------------------------------------------
Prescription relaxed_only(const EyeModel& m, double) { return m.relaxed; }
double no_range(const EyeModel&) { return 0.0; }
double range_from_file(const EyeModel&) { return -1.0; }

// --- navarro1985, navarro-wu2011-printed ---------------------------------------------------
Prescription navarro1985(const EyeModel& m, double A) {
  return navarro_accommodate(m.relaxed, A, NavarroLensIndexLaw::Navarro1985);
}
Prescription navarro_wu2011(const EyeModel& m, double A) {
  return navarro_accommodate(m.relaxed, A, NavarroLensIndexLaw::Wu2011Printed);
}

// --- gullstrand-atchison-smith --------------------------------------------------------------
// Atchison & Smith's continuous version of the Gullstrand exact eye (eye-models.md section 1):
// every curvature and thickness moves linearly from the relaxed to the accommodated state by
// x / 10.87013 with x = 1.052 A - 0.00531 A^2 + 0.000048564 A^3; the eye then focuses at -A
// within 0.002 D.
constexpr double kAtchisonSmithMaxA = 10.87013;

// A lens nucleus ends where its two faces meet; its semi-diameter is that height.
void clip_nucleus(Prescription& p) {
  for (size_t i = 0; i + 1 < p.surfaces.size(); ++i) {
    if (p.surfaces[i].name != "lens nucleus anterior") continue;
    Surface& front = p.surfaces[i];
    Surface& back = p.surfaces[i + 1];
    const std::vector<double> z = p.vertex_z_mm();
    const double h_max = std::min({front.profile.max_height(), back.profile.max_height(), 3.75});
    const double edge = meeting_height(front.profile, z[i], back.profile, z[i + 1], h_max);
    front.semi_diameter_mm = back.semi_diameter_mm = edge;
  }
}

Prescription atchison_smith(const EyeModel& m, double A) {
  Prescription p = m.relaxed;
  if (A == 0.0) {
    clip_nucleus(p);
    return p;
  }
  const double x = 1.052 * A - 0.00531 * A * A + 0.000048564 * A * A * A;
  p = interpolate(p, *m.accommodated, x / kAtchisonSmithMaxA);
  clip_nucleus(p);
  p.notes.push_back(
      fmt::format("accommodation {} D: Atchison & Smith continuous version of the "
                  "Gullstrand eye (interpolation fraction {:.5f})",
                  A, x / kAtchisonSmithMaxA));
  return p;
}
double atchison_smith_range(const EyeModel&) { return kAtchisonSmithMaxA; }

// --- interpolate-produced -------------------------------------------------------------------
// A relaxed and one accommodated state (Le Grand's 7.053 D). In between, every curvature,
// thickness and index moves linearly by one fraction f, solved so the eye produces exactly the
// requested accommodation (the idea behind Gullstrand's continuous version, whose cubic is such
// a fit). Refraction is monotonic in f, so bisection is safe.
Prescription interpolate_produced(const EyeModel& m, double A) {
  if (A == 0.0) return m.relaxed;
  const double target = refraction_D(m.relaxed) - A;
  double lo = 0.0, hi = 1.0;
  for (int it = 0; it < 60; ++it) {
    const double mid = 0.5 * (lo + hi);
    (refraction_D(interpolate(m.relaxed, *m.accommodated, mid)) > target ? lo : hi) = mid;
  }
  const double f = 0.5 * (lo + hi);
  Prescription p = interpolate(m.relaxed, *m.accommodated, f);
  p.notes.push_back(
      fmt::format("accommodation {} D: parameters interpolated linearly between the "
                  "relaxed and accommodated states (fraction {:.5f}, solved for the "
                  "produced accommodation)",
                  A, f));
  return p;
}
double produced_range(const EyeModel& m) { return refraction_D(m.relaxed) - refraction_D(*m.accommodated); }

// --- arizona --------------------------------------------------------------------------------
// The Arizona eye's published formulas in A (eye-models.md section 7), applied to the surfaces
// and the medium they name.
Prescription arizona(const EyeModel& m, double A) {
  Prescription p = m.relaxed;
  if (A == 0.0) return p;
  for (Surface& s : p.surfaces) {
    if (s.name == "cornea posterior") s.thickness_mm = 2.97 - 0.04 * A;
    if (s.name == "lens anterior") {
      s.profile = SurfaceProfile::from_radius(12.0 - 0.4 * A, -7.518749 + 1.285720 * A);
      s.thickness_mm = 3.767 + 0.04 * A;
    }
    if (s.name == "lens posterior")
      s.profile = SurfaceProfile::from_radius(-5.224557 + 0.2 * A, -1.353971 - 0.431762 * A);
  }
  for (Medium& medium : p.media)
    if (medium.name == "lens") {
      medium.index = 1.42 + 0.00256 * A - 0.00022 * A * A;
      // The model publishes n_d (this formula) and V_d (constant): the Abbe line goes through
      // the accommodated n_d, so n_F - n_C = (n_d - 1) / V_d grows with it.
      if (medium.dispersion.law == DispersionLaw::AbbeLinear) medium.dispersion.abbe_nd = medium.index;
    }
  for (Surface& s : p.surfaces)
    if (s.medium == "lens") s.index_after = p.find_medium("lens")->index;
  return p;
}

const AccommodationLaw kLaws[] = {
    {"none", "no accommodation: the model is published relaxed only", false, relaxed_only, no_range},
    {"navarro1985",
     "Navarro, Santamaria & Bescos (1985): radii, conics and distances in ln(D+1), lens index "
     "+ 9e-5 (10 D + D^2)",
     false, navarro1985, range_from_file},
    {"navarro-wu2011-printed",
     "the Navarro 1985 geometry with the lens index of Wu et al. (2011) Eq. 1 as "
     "printed, + 9e-5 ln(D+1)",
     false, navarro_wu2011, range_from_file},
    {"gullstrand-atchison-smith",
     "Atchison & Smith (2000): linear in x / 10.87013 towards the accommodated "
     "state, x = 1.052 A - 0.00531 A^2 + 0.000048564 A^3",
     true, atchison_smith, atchison_smith_range},
    {"interpolate-produced",
     "linear in one fraction towards the accommodated state, solved for the produced "
     "accommodation",
     true, interpolate_produced, produced_range},
    {"schwiegerling",
     "Schwiegerling's Arizona eye: radii, conics, thicknesses and lens index linear or quadratic "
     "in A",
     false, arizona, range_from_file},
};

}  // namespace

const AccommodationLaw& find_accommodation_law(const std::string& name) {
  for (const AccommodationLaw& law : kLaws)
    if (name == law.name) return law;
  std::string known;
  for (const std::string& n : accommodation_law_names()) known += (known.empty() ? "" : ", ") + n;
  throw OpticsError(fmt::format("unknown accommodation law '{}' (known laws: {})", name, known));
}

std::vector<std::string> accommodation_law_names() {
  std::vector<std::string> names;
  for (const AccommodationLaw& law : kLaws) names.push_back(law.name);
  return names;
}

}  // namespace eyetrace::optics
