// Floating-point rounding-error bounds for ray offsets (pbrt-v4, PBR 4th ed. section 6.8):
// the gamma(n) bound on n chained float operations, stepping to the next float up or down,
// and points moved by a transform together with the absolute error that adds. Shapes use
// these to attach a conservative error box (SurfaceInteraction::p_error) to every hit.
#pragma once
#include <bit>
#include <cstdint>
#include <limits>

#include "core/math.h"

namespace eyetrace {

// Half an ulp of 1: the relative error bound of one correctly rounded float operation.
inline constexpr float kMachineEpsilon = std::numeric_limits<float>::epsilon() * 0.5f;

// Bound on the relative error of n chained float operations: (1 + eps)^n - 1 <= n eps / (1 - n eps).
inline constexpr float gamma(int n) { return (float(n) * kMachineEpsilon) / (1.f - float(n) * kMachineEpsilon); }

inline float next_float_up(float v) {
  if (std::isinf(v) && v > 0.f) return v;
  if (v == -0.f) v = 0.f;  // -0 would step to the smallest negative denormal
  uint32_t bits = std::bit_cast<uint32_t>(v);
  bits = v >= 0.f ? bits + 1 : bits - 1;
  return std::bit_cast<float>(bits);
}

inline float next_float_down(float v) {
  if (std::isinf(v) && v < 0.f) return v;
  if (v == 0.f) v = -0.f;
  uint32_t bits = std::bit_cast<uint32_t>(v);
  bits = v > 0.f ? bits - 1 : bits + 1;
  return std::bit_cast<float>(bits);
}

// m * (p, 1) in float, with the absolute error of the result: each row is a sum of four
// products, so its rounding is at most gamma(3) times the sum of the terms' magnitudes
// (pbrt-v4's Transform::operator()(Point3fi)); an input error e is carried through the
// linear part as (gamma(3) + 1) |m| e.
inline Vec3 transform_point_with_error(const Mat4& m, const Vec3& p, const Vec3& p_error, Vec3* out_error) {
  Vec3 out(m * Vec4(p, 1.f));
  Vec3 err(0.f);
  for (int r = 0; r < 3; ++r) {
    float terms = std::abs(m[0][r] * p.x) + std::abs(m[1][r] * p.y) + std::abs(m[2][r] * p.z) + std::abs(m[3][r]);
    float carried = std::abs(m[0][r]) * p_error.x + std::abs(m[1][r]) * p_error.y + std::abs(m[2][r]) * p_error.z;
    err[r] = gamma(3) * terms + (gamma(3) + 1.f) * carried;
  }
  *out_error = err;
  return out;
}

}  // namespace eyetrace
