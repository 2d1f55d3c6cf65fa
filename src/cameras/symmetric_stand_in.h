// Rotationally symmetric stand-ins that let the lens-system camera render a system that is not
// rotationally symmetric (a toric cornea or spectacle lens, a decentred iris, a measured
// wavefront as a phase plate on the iris).
// The camera's tables (field mapping, pupil regions, brightness normalisation) are built for
// one meridian and rotated to every azimuth, which needs symmetry; every ray is still traced
// through the real system. Two stand-ins serve two different purposes:
//
// - symmetric_equivalent: the same eye with each biconic replaced by its spherical-equivalent
//   conic and every decentration, tilt and phase plate removed. It defines which retina point a pixel shows
//   (the field mapping) and the brightness normalisation, so an astigmatic or decentred eye
//   frames the scene and exposes it as the same eye without those changes does.
// - pupil_envelope: a system through which at least every ray of the real one passes, from
//   each retina point. Rays are drawn uniformly in its pupil regions and traced through the
//   real system, which rejects the ones it blocks: unbiased because the envelope's region
//   contains the real one (the density 1 / area is that of the larger region; the rejected
//   part contributes zero). It keeps the surfaces between the retina and the iris, which must
//   therefore be rotationally symmetric and centred, makes the iris a centred opening that
//   holds the decentred one, and replaces everything in front of the iris by one flat,
//   unlimited, non-refracting surface: a ray that passes the iris of the envelope may still
//   be bent or blocked by the real cornea or spectacle lens, never the other way round.
#pragma once

#include "optics/prescription.h"

namespace eyetrace {

// Biconic -> conic of the mean curvature and mean conic; placements and phase plates removed.
optics::Prescription symmetric_equivalent(const optics::Prescription& p);

// The envelope described above. Throws optics::OpticsError naming the surface when a surface
// between the iris and the image is not rotationally symmetric and centred, or when the iris
// is tilted: the camera cannot bound those systems' pupil regions (`eyetrace optics` still
// analyses them).
optics::Prescription pupil_envelope(const optics::Prescription& p);

}  // namespace eyetrace
