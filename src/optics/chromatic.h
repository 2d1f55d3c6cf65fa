// Chromatic aberration of a prescription, from its media's dispersion laws (medium.h: indices are
// anchored at the reference wavelength, so the reference-wavelength system is the published one
// and only the change of index with wavelength comes from the laws). Geometry (retina included)
// is held fixed; only the indices change with wavelength.
//
// Longitudinal: the chromatic difference of refraction. refraction_D (paraxial.h: the object
// vergence at the first vertex focused on the image surface, negative = myopic) computed at each
// wavelength from at_wavelength(); LCA = refraction(longest) - refraction(shortest), > 0 for
// normal dispersion (blue focuses in front of red, so the eye is more myopic in blue).
//
// Transverse: for one object point, the chief rays (through the centre of the aperture stop) at
// a short and a long wavelength reach the image surface at two points. Each point is seen in the
// direction of the visual field angle that maps to it: the angle of the chief ray, at the
// prescription's own wavelength (wavelength_nm, the camera's) and from an object at infinity,
// that lands there. This is the eye cameras' `mapping "angle"` (pixels linear in that angle), so
// the TCA is the colour fringe a render measures, in degrees of visual angle. Signed: TCA =
// angle(short) - angle(long), positive when the short-wavelength image is seen farther from the
// axis than the long one (in the direction of the field); the retina displacement is signed the
// same way (arc length along a curved image surface, height on a flat one). The centroid TCA is
// the same with the centroids of the real-ray spots (spot.h: the real entrance pupil filled) in
// place of the chief rays' points: where the colour fringes of a blurred image centre. It
// depends on the pupil (it approaches the chief-ray TCA as the pupil closes).
#pragma once

#include <limits>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "optics/prescription.h"
#include "optics/sequential_trace.h"

namespace eyetrace::optics {

struct ChromaticOptions {
  double min_wavelength_nm = 400.0;  // chromatic difference of refraction from ...
  double max_wavelength_nm = 700.0;  // ... to, both included
  double step_nm = 10.0;             // between the wavelengths listed (the last step may be shorter)
  double tca_short_nm = 450.0;       // transverse chromatic aberration between ...
  double tca_long_nm = 650.0;        // ... these two
  // Pupil grid of the spot centroids of the centroid TCA (spot.h SpotOptions::grid); 0 = skip it.
  int centroid_grid = 64;
};

// Throws OpticsError naming the option ("chromatic range", "chromatic step", "tca wavelengths")
// when a wavelength lies outside [kMinWavelength_nm, kMaxWavelength_nm] (where the dispersion
// laws are used), min >= max, the step is not in (0, max - min], or short >= long.
void validate(const ChromaticOptions& options);

struct RefractionAtWavelength {
  double wavelength_nm = 0.0;
  double refraction_D = 0.0;
};

// refraction_D at min, min + step, ..., max (max always included). Validates the options.
std::vector<RefractionAtWavelength> chromatic_refraction(const Prescription& p, const ChromaticOptions& options);

// The chief ray of one object point at one wavelength.
struct ChiefRay {
  bool ok = false;
  std::string lost;                  // why not ok: the surface and the reason
  Ray object_ray;                    // the aimed ray as launched in object space (ok only)
  glm::dvec3 image_mm{0.0};          // where it meets the image surface
  double image_coordinate_mm = 0.0;  // signed arc length (height if flat) from the image vertex, > 0 on
                                     // the side where a positive field images (-y)
};

// Object point: at infinity in the direction of field_deg (as SpotOptions: |field| < 85, source
// above the axis for a positive field), or, for a finite object_distance_m, at that distance from
// the centre of the prescription's paraxial entrance pupil in that direction. The chief ray is
// aimed (Newton on its start point) until it crosses the stop plane within 1e-12 mm of the axis,
// then traced to the image surface with the real apertures; a lost ray is reported, not thrown.
// `object_p` fixes the object point (its entrance pupil places a finite object) so that the same
// point is traced at every wavelength; p is the system at the wavelength wanted.
ChiefRay trace_chief_ray(const Prescription& p, double field_deg,
                         double object_distance_m = std::numeric_limits<double>::infinity(),
                         const Prescription* object_p = nullptr);

// Signed coordinate (ChiefRay::image_coordinate_mm) of a point on or near the image surface, on
// the y-z meridian: projected from the centre of curvature onto a curved surface.
double image_coordinate_mm(const Prescription& p, const glm::dvec3& point);

// Visual field angle (deg) whose chief ray, from an object at infinity at p's wavelength, meets
// the image surface at image_coordinate_mm (ChiefRay's signed coordinate). NaN when no chief ray
// gets there (lost on the way).
double visual_angle_deg(const Prescription& p, double image_coordinate_mm);

struct TransverseChromatic {
  double field_deg = 0.0;
  bool ok = false;  // false when a chief ray is lost at one of the wavelengths
  std::string lost;
  double tca_arcmin = 0.0;       // visual angle of the short-wavelength image minus the long one's
  double retina_um = 0.0;        // image coordinate of the short-wavelength image minus the long one's
  double short_angle_deg = 0.0;  // the two visual angles
  double long_angle_deg = 0.0;
  bool centroid_ok = false;  // false when skipped or a spot is empty
  double centroid_tca_arcmin = 0.0;
  double centroid_retina_um = 0.0;
};

// TCA of the object point of field_deg (and object_distance_m) between options.tca_short_nm and
// options.tca_long_nm. Validates the options.
TransverseChromatic transverse_chromatic_aberration(const Prescription& p, double field_deg, double object_distance_m,
                                                    const ChromaticOptions& options);

// Name of a dispersion law as the data files spell it ("none", "navarro-herzberger", ...).
const char* to_string(DispersionLaw law);

}  // namespace eyetrace::optics
