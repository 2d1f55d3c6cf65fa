// First-order (paraxial) analysis of a prescription with 2x2 y-nu matrices: equivalent power,
// cardinal points, pupils, refraction and the image position that gives a wanted refraction.
// Conics do not enter (paraxially every conic is its osculating sphere); a biconic enters as
// its spherical equivalent (the mean of its meridians' curvatures: sphero_cylinder.h has the
// per-meridian analysis) and decentrations and tilts as nothing (to first order they add prism,
// not power), except the stop's decentration, which moves the pupils' centres. Positions are in mm
// from the first vertex (the anterior corneal vertex for an eye), +z towards the image.
#pragma once

#include "optics/prescription.h"

namespace eyetrace::optics {

// (y, n u) -> (A y + B n u, C y + D n u); determinant 1 with reduced angles.
struct RayMatrix {
  double A = 1.0, B = 0.0, C = 0.0, D = 1.0;
};

// Matrix from just before surface `first`'s vertex to just after surface `last` (at its vertex),
// refracting at first..last and transferring between them. Image surfaces do not refract.
RayMatrix system_matrix(const Prescription& p, int first, int last);

struct Pupil {
  double position_mm = 0.0;  // from the first vertex
  double diameter_mm = 0.0;
  double magnification = 0.0;  // pupil diameter / stop diameter
  // The image of the stop's centre in the pupil plane: the stop's decentration times the
  // magnification (0 for a centred stop). The chief ray of an axial object aims at it.
  double centre_x_mm = 0.0, centre_y_mm = 0.0;
};

struct ParaxialData {
  double power_D = 0.0;  // equivalent power (object space air for an eye)
  double object_index = 1.0;
  double image_index = 1.0;
  // Cardinal points, positions from the first vertex.
  double front_focal_point_mm = 0.0;      // F
  double back_focal_point_mm = 0.0;       // F'
  double front_principal_point_mm = 0.0;  // H
  double back_principal_point_mm = 0.0;   // H'
  double front_nodal_point_mm = 0.0;      // N
  double back_nodal_point_mm = 0.0;       // N'
  double front_focal_length_mm = 0.0;     // H -> F, = -n / P (negative)
  double back_focal_length_mm = 0.0;      // H' -> F', = n' / P
  double back_focal_distance_mm = 0.0;    // last refracting vertex -> F'
  double front_focal_distance_mm = 0.0;   // first vertex -> F (negative)
  Pupil entrance_pupil;                   // image of the stop in object space
  Pupil exit_pupil;                       // image of the stop in image space
  double refraction_D = 0.0;              // object vergence at the first vertex imaged on the image
  double axial_length_mm = 0.0;           // first vertex -> image vertex
  double far_point_m = 0.0;               // -1 / refraction (+inf when emmetropic)
};

// Throws OpticsError for an afocal system (zero power) or a prescription without a stop.
ParaxialData paraxial_analysis(const Prescription& p);

// Object vergence (D) at the first vertex that is focused on the image surface: 0 emmetropic,
// negative myopic (far point at -1/V m in front), positive hyperopic; minus the near-point
// vergence for an accommodated eye.
double refraction_D(const Prescription& p);

// Distance from the first vertex to where the image surface must be for the system to have the
// given refraction (object vergence in D; 0 = focus at infinity). Throws when that image is
// virtual (behind the last refracting surface).
double image_position_for_refraction(const Prescription& p, double refraction_D);

// Moves the image surface (changes the thickness before it) so the refraction is refraction_D.
// For an eye this is a change of vitreous depth, i.e. of axial length.
void set_refraction(Prescription& p, double refraction_D);

}  // namespace eyetrace::optics
