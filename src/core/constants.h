// The renderer's shared constants, declared once: pi and its relatives in float (rendering)
// and double (camera set-up, tests), the degree conversion, infinity and the largest float
// below 1. The optics library (which may not include the renderer) uses std::numbers directly.
#pragma once
#include <limits>
#include <numbers>

namespace eyetrace {

inline constexpr double kPiDouble = std::numbers::pi;
inline constexpr double kTwoPiDouble = 2.0 * std::numbers::pi;
inline constexpr double kRadiansPerDegree = std::numbers::pi / 180.0;
inline constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;

inline constexpr float kPi = std::numbers::pi_v<float>;
inline constexpr float kInvPi = std::numbers::inv_pi_v<float>;
inline constexpr float kInv2Pi = 0.5f * std::numbers::inv_pi_v<float>;
inline constexpr float kInfinity = std::numeric_limits<float>::infinity();
// Largest float strictly below 1, so that samples stay in [0, 1).
inline constexpr float kOneMinusEpsilon = 0x1.fffffep-1f;

}  // namespace eyetrace
