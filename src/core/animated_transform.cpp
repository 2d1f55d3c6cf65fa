#include "core/animated_transform.h"

#include <cmath>
#include <stdexcept>

namespace eyetrace {

namespace {

// Slerp along the shorter arc, as Embree interpolates a quaternion instance (its slerp: the
// normalised linear blend when the two are within 0.9995 in cosine, where the arc formula
// loses precision).
glm::quat slerp_shorter(const glm::quat& q0, glm::quat q1, float u) {
  float cos_theta = glm::dot(q0, q1);
  if (cos_theta < 0.f) {
    q1 = -q1;
    cos_theta = -cos_theta;
  }
  if (cos_theta > 0.9995f) return glm::normalize(q0 * (1.f - u) + q1 * u);
  const float phi = u * std::acos(std::min(cos_theta, 1.f));
  glm::quat perp = glm::normalize(q1 - q0 * cos_theta);
  return q0 * std::cos(phi) + perp * std::sin(phi);
}

}  // namespace

AnimatedTransform::AnimatedTransform(const Transform& start, float start_time, const Transform& end, float end_time)
    : start_(start), end_(end), start_time_(start_time), end_time_(end_time), animated_(!(start == end)) {
  if (!animated_) return;
  parts_[0] = decompose(start);
  parts_[1] = decompose(end);
  // pbrt-v4 flips the second rotation so that the interpolation takes the shorter way round.
  if (glm::dot(parts_[0].rotation, parts_[1].rotation) < 0.f) parts_[1].rotation = -parts_[1].rotation;
  // U's last diagonal entry carries the handedness: if it changes sign the blend passes through
  // a flat (singular) transform at some time, which no surface survives.
  if ((parts_[0].upper[2][2] < 0.f) != (parts_[1].upper[2][2] < 0.f))
    throw std::domain_error("the start and end transforms differ in handedness (one mirrors, the other does not)");
}

// M = T R U: T from the last column; the linear part L = R U by Gram-Schmidt on L's columns
// (in double), R a proper rotation; when L swaps handedness the sign goes to U's last diagonal
// entry so that R stays a rotation (a quaternion cannot hold a reflection).
AnimatedTransform::Parts AnimatedTransform::decompose(const Transform& t) {
  const Mat4& m = t.matrix();
  if (m[0][3] != 0.f || m[1][3] != 0.f || m[2][3] != 0.f || m[3][3] != 1.f)
    throw std::domain_error("a projective transform cannot be animated");
  Parts p;
  p.translation = Vec3(m[3]);
  glm::dvec3 l[3] = {glm::dvec3(m[0]), glm::dvec3(m[1]), glm::dvec3(m[2])};
  glm::dvec3 q[3];
  glm::dmat3 u(0.0);
  for (int c = 0; c < 3; ++c) {
    glm::dvec3 v = l[c];
    for (int k = 0; k < c; ++k) {
      u[c][k] = glm::dot(q[k], v);  // modified Gram-Schmidt: project the running remainder
      v -= u[c][k] * q[k];
    }
    u[c][c] = glm::length(v);
    if (!(u[c][c] > 0.0) || !std::isfinite(u[c][c])) throw std::domain_error("a singular transform cannot be animated");
    q[c] = v / u[c][c];
  }
  glm::dmat3 r(q[0], q[1], q[2]);
  if (glm::determinant(r) < 0.0) {
    r[2] = -r[2];
    u[2][2] = -u[2][2];
  }
  p.rotation = glm::normalize(glm::quat_cast(glm::mat3(r)));
  p.upper = glm::mat3(u);
  return p;
}

Mat4 AnimatedTransform::compose(const Vec3& translation, const glm::quat& rotation, const glm::mat3& upper) {
  Mat4 m(glm::mat3_cast(rotation) * upper);
  m[3] = Vec4(translation, 1.f);
  return m;
}

float AnimatedTransform::fraction(float time) const {
  if (!(time > start_time_)) return 0.f;  // also a NaN time: the start keyframe
  if (time >= end_time_) return 1.f;
  return (time - start_time_) / (end_time_ - start_time_);
}

Transform AnimatedTransform::interpolate(float time) const { return at_fraction(fraction(time)); }

Transform AnimatedTransform::at_fraction(float u) const {
  if (!animated_ || u <= 0.f) return start_;
  if (u >= 1.f) return end_;
  const Parts& a = parts_[0];
  const Parts& b = parts_[1];
  Vec3 translation = (1.f - u) * a.translation + u * b.translation;
  glm::quat rotation = slerp_shorter(a.rotation, b.rotation, u);
  glm::mat3 upper = (1.f - u) * a.upper + u * b.upper;
  // U's diagonal entries keep their signs between the keyframes (the constructor refuses a
  // change of handedness; Gram-Schmidt makes the first two positive), so the blend is invertible.
  // The inverse from the factors, U^-1 R^T T^-1 (U upper triangular with a non-zero diagonal),
  // not by a general inversion: no determinant threshold to trip over for a tiny but valid
  // scale, and nothing to throw inside a render thread.
  const glm::dmat3 ud(upper);
  glm::dmat3 u_inv(0.0);
  for (int c = 0; c < 3; ++c) {
    u_inv[c][c] = 1.0 / ud[c][c];
    for (int r = c - 1; r >= 0; --r) {
      double sum = 0.0;
      for (int k = r + 1; k <= c; ++k) sum += ud[k][r] * u_inv[c][k];
      u_inv[c][r] = -sum / ud[r][r];
    }
  }
  const glm::dmat3 linear_inv = u_inv * glm::transpose(glm::dmat3(glm::mat3_cast(rotation)));
  Mat4 inv = Mat4(glm::mat3(linear_inv));
  inv[3] = Vec4(Vec3(-(linear_inv * glm::dvec3(translation))), 1.f);
  return Transform(compose(translation, rotation, upper), inv);
}

RTCQuaternionDecomposition AnimatedTransform::embree_keyframe(int i) const {
  const Parts q = animated_ ? parts_[i] : decompose(start_);
  RTCQuaternionDecomposition d;
  rtcInitQuaternionDecomposition(&d);
  // U's entries: upper[col][row]; Embree's S has scale on the diagonal and skew_ab at row a, column b.
  rtcQuaternionDecompositionSetScale(&d, q.upper[0][0], q.upper[1][1], q.upper[2][2]);
  rtcQuaternionDecompositionSetSkew(&d, q.upper[1][0], q.upper[2][0], q.upper[2][1]);
  rtcQuaternionDecompositionSetQuaternion(&d, q.rotation.w, q.rotation.x, q.rotation.y, q.rotation.z);
  rtcQuaternionDecompositionSetTranslation(&d, q.translation.x, q.translation.y, q.translation.z);
  return d;
}

}  // namespace eyetrace
