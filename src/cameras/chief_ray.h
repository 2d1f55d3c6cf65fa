// Chief-ray aiming for the lens-system camera: the ray from a retina point that passes through
// the centre of the aperture stop. Rays leave the retina towards a point (q, 0, z_plane) of the
// sampling plane (see pupil_sampler.h); aiming solves for q so the ray crosses the stop plane on
// the axis. Used at construction only (the field-angle table, the pupil-region centres).
#pragma once

#include <optional>

#include <glm/vec3.hpp>

#include "optics/prescription.h"
#include "optics/sequential_trace.h"

namespace eyetrace {

// The system with every clear aperture but the stop's opened as far as its surface can go: to
// the conic's reach and the height where it meets a neighbouring surface (a lens rim). Chief
// rays are aimed in it, so the field-angle mapping is a property of the eye's geometry that
// goes on past the field where the published (partly arbitrary) semi-diameters start to
// vignette the chief ray; real rays are still traced with the real apertures.
optics::Prescription with_extended_apertures(const optics::Prescription& p);
// with_extended_apertures, or p itself when the opened system does not validate.
optics::Prescription aiming_prescription(const optics::Prescription& p);

// A ray from `from` through the sampling-plane point (q, y, z_plane), traced in reverse from the
// surface just in front of the image to `last` (0 = out into object space).
optics::TraceResult trace_towards_plane(const optics::CompiledSystem& system, const glm::dvec3& from, double q,
                                        double y, double z_plane, int last = 0);

// q of the chief ray from a retina point on the +x meridian (from.y == 0), starting the search
// at q_guess; nullopt when no ray from `from` reaches the stop plane near its centre.
std::optional<double> aim_chief_ray(const optics::CompiledSystem& system, const glm::dvec3& from, double z_plane,
                                    double q_guess);

}  // namespace eyetrace
