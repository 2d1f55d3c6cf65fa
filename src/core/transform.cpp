#include "core/transform.h"

#include <glm/gtc/matrix_inverse.hpp>
#include <stdexcept>

namespace eyetrace {

Transform::Transform(const Mat4& m) : m_(m) {
  // Double precision for the inverse: scene files chain many transforms.
  glm::dmat4 md(m);
  double det = glm::determinant(md);
  if (!std::isfinite(det) || std::abs(det) < 1e-30)
    throw std::domain_error("transform matrix is singular or not finite");
  m_inv_ = Mat4(glm::inverse(md));
}

bool Transform::swaps_handedness() const { return glm::determinant(glm::mat3(m_)) < 0.f; }

Vec3 Transform::point(const Vec3& p) const {
  Vec4 r = m_ * Vec4(p, 1.f);
  return r.w == 1.f ? Vec3(r) : Vec3(r) / r.w;
}

Transform translate(const Vec3& d) {
  Mat4 m(1.f), mi(1.f);
  m[3] = Vec4(d, 1.f);
  mi[3] = Vec4(-d, 1.f);
  return Transform(m, mi);
}

Transform scale(const Vec3& s) {
  Mat4 m(1.f), mi(1.f);
  for (int i = 0; i < 3; ++i) {
    m[i][i] = s[i];
    mi[i][i] = 1.f / s[i];
  }
  return Transform(m, mi);
}

Transform rotate(float degrees, const Vec3& axis) {
  Vec3 a = glm::normalize(axis);
  float s = std::sin(radians(degrees)), c = std::cos(radians(degrees));
  // Row-major formula from pbrt; glm indexes [column][row].
  float r[3][3] = {{a.x * a.x + (1 - a.x * a.x) * c, a.x * a.y * (1 - c) - a.z * s, a.x * a.z * (1 - c) + a.y * s},
                   {a.x * a.y * (1 - c) + a.z * s, a.y * a.y + (1 - a.y * a.y) * c, a.y * a.z * (1 - c) - a.x * s},
                   {a.x * a.z * (1 - c) - a.y * s, a.y * a.z * (1 - c) + a.x * s, a.z * a.z + (1 - a.z * a.z) * c}};
  Mat4 m(1.f);
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 3; ++col) m[col][row] = r[row][col];
  return Transform(m, glm::transpose(m));
}

Transform look_at(const Vec3& eye, const Vec3& look, const Vec3& up) {
  Vec3 dir = look - eye;
  if (glm::length(dir) == 0.f) throw std::domain_error("eye and look points coincide");
  dir = glm::normalize(dir);
  Vec3 upn = glm::normalize(up);
  Vec3 right = glm::cross(upn, dir);
  if (glm::length(right) == 0.f) throw std::domain_error("up vector and viewing direction are parallel");
  right = glm::normalize(right);
  Vec3 new_up = glm::cross(dir, right);
  Mat4 world_from_camera(Vec4(right, 0.f), Vec4(new_up, 0.f), Vec4(dir, 0.f), Vec4(eye, 1.f));
  return Transform(glm::inverse(world_from_camera), world_from_camera);
}

Transform perspective(float fov_deg, float n, float f) {
  Mat4 persp(1.f);
  persp[2][2] = f / (f - n);
  persp[3][2] = -f * n / (f - n);
  persp[2][3] = 1.f;
  persp[3][3] = 0.f;
  float inv_tan = 1.f / std::tan(radians(fov_deg) / 2.f);
  return scale(Vec3(inv_tan, inv_tan, 1.f)) * Transform(persp);
}

}  // namespace eyetrace
