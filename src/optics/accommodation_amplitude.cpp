// Hofstetter's (1950) age-amplitude relations (see accommodation_amplitude.h).
#include "optics/accommodation_amplitude.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "optics/optics_error.h"
#include "optics/paraxial.h"

namespace eyetrace::optics {

AccommodationAmplitude hofstetter_amplitude(double age_years) {
  if (!std::isfinite(age_years) || age_years < 0.0 || age_years > kMaxAge_years)
    throw OpticsError("age", fmt::format("{} years is outside [0, {}] years", age_years, kMaxAge_years));
  return {std::max(0.0, 15.0 - 0.25 * age_years), std::max(0.0, 18.5 - 0.3 * age_years),
          std::max(0.0, 25.0 - 0.4 * age_years)};
}

double produced_accommodation_D(const Prescription& relaxed, const Prescription& accommodated) {
  return refraction_D(relaxed) - refraction_D(accommodated);
}

void check_accommodation_for_age(double age_years, double accommodation_D, double produced_D) {
  const AccommodationAmplitude a = hofstetter_amplitude(age_years);
  // 1e-9 D: round-off of the two refractions, far below any clinical difference.
  if (produced_D <= a.maximum_D + 1e-9) return;
  throw OpticsError(
      "accommodation",
      fmt::format("{} D ({:.2f} D produced) is beyond the accommodation amplitude of a {}-year-old eye: {:.2f} D by "
                  "Hofstetter's (1950) maximum-amplitude relation 25 - 0.4 x age (his mean 18.5 - 0.3 x age gives "
                  "{:.2f} D)",
                  accommodation_D, produced_D, age_years, a.maximum_D, a.mean_D));
}

}  // namespace eyetrace::optics
