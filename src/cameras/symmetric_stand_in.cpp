#include "cameras/symmetric_stand_in.h"

#include <cmath>

#include <fmt/format.h>

#include "optics/optics_error.h"

namespace eyetrace {

namespace {

bool symmetric_and_centred(const optics::Surface& s) {
  return s.profile.rotationally_symmetric() && s.placement.is_identity() && !s.phase_plate;
}

}  // namespace

optics::Prescription symmetric_equivalent(const optics::Prescription& p) {
  optics::Prescription out = p;
  for (optics::Surface& s : out.surfaces) {
    if (!s.profile.rotationally_symmetric())
      s.profile = optics::SurfaceProfile::from_curvature(s.profile.mean_curvature(),
                                                         0.5 * (s.profile.conic + s.profile.cross_conic));
    s.placement = {};
    s.phase_plate = nullptr;
  }
  return out;
}

optics::Prescription pupil_envelope(const optics::Prescription& p) {
  const int stop = p.stop_index();
  if (stop < 0) throw optics::OpticsError(fmt::format("'{}' has no aperture stop", p.name));
  const optics::Surface& iris = p.surfaces[static_cast<size_t>(stop)];
  for (size_t i = static_cast<size_t>(stop) + 1; i < p.surfaces.size(); ++i)
    if (!symmetric_and_centred(p.surfaces[i]))
      throw optics::OpticsError(
          fmt::format("surface {} ('{}') lies between the iris and the image and is not rotationally symmetric and "
                      "centred; the camera renders eyes whose asymmetry lies in front of the iris (cornea, "
                      "spectacle or contact lens, a decentred iris); `eyetrace optics` analyses this one",
                      i, p.surfaces[i].name));
  if (iris.placement.tilt_x_deg != 0.0 || iris.placement.tilt_y_deg != 0.0)
    throw optics::OpticsError(
        fmt::format("the iris '{}' is tilted; the camera renders a decentred iris, not a tilted one", iris.name));

  optics::Prescription out = p;
  out.surfaces.clear();
  if (stop > 0) {
    // One flat surface in the medium in front of the iris, where the front surfaces were: the
    // iris and everything behind it keep their vertex positions.
    const optics::Surface& before = p.surfaces[static_cast<size_t>(stop) - 1];
    optics::Surface front;
    front.name = "envelope front";
    front.profile = optics::SurfaceProfile::plane();
    front.thickness_mm = p.vertex_z_mm()[static_cast<size_t>(stop)];
    front.medium = before.medium;
    front.index_after = before.index_after;
    out.object_index = before.index_after;
    out.surfaces.push_back(front);
  }
  optics::Surface opening = iris;
  // The centred circle that holds the decentred opening.
  if (iris.limited())
    opening.semi_diameter_mm += std::hypot(iris.placement.decentre_x_mm, iris.placement.decentre_y_mm);
  opening.placement = {};
  // A phase plate on the iris (a measured wavefront) bends rays where they cross the iris's
  // plane and blocks those beyond its disc: it never lets through a ray the opening stops.
  opening.phase_plate = nullptr;
  out.surfaces.push_back(opening);
  out.surfaces.insert(out.surfaces.end(), p.surfaces.begin() + stop + 1, p.surfaces.end());
  return out;
}

}  // namespace eyetrace
