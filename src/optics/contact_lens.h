// A soft contact lens on the cornea (the eye cameras' `"float contactlens"`), as a surface layer.
//
// Model. The lens conforms to the cornea: its back surface IS the anterior corneal surface (same
// radius, conic and, on an astigmatic cornea, the same biconic), with no tear layer between them
// (the post-lens tear film is a few micrometres thick and, conforming, has no power). So the
// prescription gains one surface in front of the cornea: the lens's front, a layer of index
// kContactLensIndex (1.43, typical of hydrogel and silicone-hydrogel soft lenses, 1.40-1.44)
// whose centre thickness is kContactLensThickness_mm (0.1 mm), or more for a plus lens, so that
// the layer is at least kMinContactLensEdge_mm thick at the cornea's clear semi-diameter. The
// front's curvature is solved in each principal meridian of the cornea so that the lens's
// back-vertex power IN AIR is the requested power: BVP = F1 / (1 - (t/n) F1) + (1 - n) c_back,
// F1 = (n - 1) c_front. Its conic is the cornea's. Because the back surface of the lens and the
// cornea coincide, the air gap of the "lens in air" has zero thickness and the lens's power adds
// to the eye's refraction at the corneal vertex exactly (to first order): a -3.00 D contact lens
// corrects an eye of -3.00 D refraction at the cornea. The lens's front vertex becomes z = 0.
#pragma once

#include "optics/prescription.h"

namespace eyetrace::optics {

inline constexpr double kContactLensIndex = 1.43;
inline constexpr double kContactLensThickness_mm = 0.1;
inline constexpr double kMinContactLensEdge_mm = 0.05;
inline constexpr double kMaxContactLensPower_D = 20.0;

// Puts the lens on surface 0 of `eye` (the anterior cornea, in air). Throws OpticsError
// ("contactlens") for a non-finite power or one beyond +-kMaxContactLensPower_D, and when the
// front surface cannot span the cornea's clear aperture.
void add_contact_lens(Prescription& eye, double power_D);

}  // namespace eyetrace::optics
