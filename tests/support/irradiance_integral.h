// Independent irradiance integral at a retina point of a lens-system camera: directions drawn on
// a jittered grid uniformly in a cone (half-angle 35 degrees around the direction to the
// sampling plane's centre), each traced through the camera's real system; E = solid angle x
// mean(pass x cos(theta_retina)). Shares nothing with the camera's pupil sampler or weights, so
// the camera's mean weight must be weight_normalisation() x E.
#pragma once

#include <cmath>
#include <random>

#include <glm/geometric.hpp>

#include "cameras/lens_system_camera.h"
#include "core/constants.h"

namespace eyetrace::test {

inline double integrate_irradiance(const LensSystemCamera& cam, const LensSystemCamera::RetinaPoint& rp, int n) {
  const glm::dvec3 axis = glm::normalize(glm::dvec3(0.0, 0.0, cam.pupil().z_plane()) - rp.position);
  const double beta = 35.0 * kPiDouble / 180.0, cos_beta = std::cos(beta);
  glm::dvec3 t1 = glm::normalize(glm::cross(axis, glm::dvec3(0.0, 1.0, 0.0)));
  if (!std::isfinite(t1.x)) t1 = glm::dvec3(1.0, 0.0, 0.0);
  const glm::dvec3 t2 = glm::cross(axis, t1);
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double sum = 0.0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double cos_t = 1.0 - (i + u(rng)) / n * (1.0 - cos_beta);
      const double sin_t = std::sqrt(1.0 - cos_t * cos_t), phi = 2.0 * kPiDouble * (j + u(rng)) / n;
      const glm::dvec3 d = cos_t * axis + sin_t * (std::cos(phi) * t1 + std::sin(phi) * t2);
      const double cos_r = glm::dot(d, rp.normal);
      if (cos_r <= 0.0) continue;
      if (cam.system().trace_range({rp.position, d}, cam.system().image_index() - 1, 0).ok()) sum += cos_r;
    }
  return 2.0 * kPiDouble * (1.0 - cos_beta) * sum / (double(n) * n);
}

}  // namespace eyetrace::test
