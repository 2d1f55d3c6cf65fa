// The accommodation amplitude of an eye of a given age (the eye cameras' `"float age"`), from
// Hofstetter's age relations (Hofstetter HW, "A useful age-amplitude formula", Optometry World
// 38(12):42-45, 1950; fitted to Duane's 1922 data), in dioptres, never below 0:
//   minimum 15 - 0.25 age,  mean 18.5 - 0.3 age,  maximum 25 - 0.4 age.
// The eye cameras refuse accommodation beyond the MAXIMUM curve: an eye camera models one
// person, and refusing what a normal eye of that age can still do (the minimum or mean curve
// would) would refuse real patients; beyond the maximum no eye of that age in Duane's data
// accommodates. The amplitude is compared with the accommodation the eye PRODUCES (the change of
// its refraction, relaxed minus accommodated), since the cameras' `accommodation` is each model's
// own parameter (Navarro's D is not the produced accommodation).
#pragma once

#include "optics/prescription.h"

namespace eyetrace::optics {

inline constexpr double kMaxAge_years = 120.0;

struct AccommodationAmplitude {
  double minimum_D = 0.0, mean_D = 0.0, maximum_D = 0.0;
};

// Throws OpticsError ("age") for a non-finite age or one outside [0, kMaxAge_years].
AccommodationAmplitude hofstetter_amplitude(double age_years);

// The accommodation `accommodated` produces over `relaxed` (the same eye at 0): refraction of the
// relaxed eye minus that of the accommodated one, in D.
double produced_accommodation_D(const Prescription& relaxed, const Prescription& accommodated);

// Throws OpticsError ("accommodation") naming the age, the amplitude and the relation when the
// produced accommodation exceeds Hofstetter's maximum amplitude at that age.
// `accommodation_D` is the option as given, for the message.
void check_accommodation_for_age(double age_years, double accommodation_D, double produced_D);

}  // namespace eyetrace::optics
