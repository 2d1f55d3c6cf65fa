// Affine/projective transforms with their inverse, as pbrt keeps them, so normals and
// inverse mappings never need a run-time matrix inversion.
#pragma once
#include "core/math.h"

namespace eyetrace {

class Transform {
 public:
  Transform() = default;
  explicit Transform(const Mat4& m);  // computes the inverse; throws std::domain_error if singular
  Transform(const Mat4& m, const Mat4& m_inv) : m_(m), m_inv_(m_inv) {}

  const Mat4& matrix() const { return m_; }
  const Mat4& inverse_matrix() const { return m_inv_; }
  Transform inverse() const { return Transform(m_inv_, m_); }
  bool is_identity() const { return m_ == Mat4(1.f); }
  // True when the transform flips handedness (negative determinant of the 3x3 part).
  bool swaps_handedness() const;

  Vec3 point(const Vec3& p) const;
  Vec3 vector(const Vec3& v) const { return Vec3(m_ * Vec4(v, 0.f)); }
  // Normals transform by the inverse transpose.
  Vec3 normal(const Vec3& n) const { return Vec3(glm::transpose(m_inv_) * Vec4(n, 0.f)); }

  Transform operator*(const Transform& t) const { return Transform(m_ * t.m_, t.m_inv_ * m_inv_); }
  bool operator==(const Transform& t) const { return m_ == t.m_; }

 private:
  Mat4 m_{1.f};
  Mat4 m_inv_{1.f};
};

Transform translate(const Vec3& delta);
Transform scale(const Vec3& s);
Transform rotate(float degrees, const Vec3& axis);
// pbrt's LookAt: the camera at `eye` looks towards `look`, `up` fixes the roll. Returns the
// camera-from-world transform (left-handed camera space: +x right, +y up, +z forward).
Transform look_at(const Vec3& eye, const Vec3& look, const Vec3& up);
// pbrt's perspective projection (camera space to a screen space whose z maps [n, f] to [0, 1]).
Transform perspective(float fov_deg, float n, float f);

}  // namespace eyetrace
