// Measured scattering coefficients of real materials by name ("Skin1", "Ketchup", "Regular
// Milk", ...), as pbrt-v4 carries them (media.cpp, GetMediumScatteringProperties): RGB reduced
// scattering sigma'_s and absorption sigma_a in mm^-1, from Jensen et al. 2001 and Narasimhan
// et al. 2006 (cited at the table). Values copied as pbrt-v4 has them.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "core/math.h"

namespace eyetrace {

struct MeasuredMedium {
  const char* name;
  RGB sigma_prime_s;  // reduced scattering coefficient, mm^-1
  RGB sigma_a;        // absorption coefficient, mm^-1
};

// The named medium, or null.
const MeasuredMedium* find_measured_medium(std::string_view name);
std::vector<std::string> measured_medium_names();

}  // namespace eyetrace
