// Angle constants of the optics library, defined once (src/optics may not include core/constants.h).
#pragma once

#include <numbers>

namespace eyetrace::optics {

inline constexpr double kTwoPi = 2.0 * std::numbers::pi;
inline constexpr double kRadPerDeg = std::numbers::pi / 180.0;

}  // namespace eyetrace::optics
