// The image surface of a lens-system camera (the retina of an eye, the film of a lens) described
// along one meridian by arc length. The system is rotationally symmetric, so every table the
// camera precomputes lives on the +x meridian and is rotated to a pixel's azimuth per ray.
// Arc length (not lateral height) is the parameter: it is what the "retina" mapping is linear
// in, and it stays well-conditioned up to the equator, where the lateral height stops growing.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/vec2.hpp>

#include "core/constants.h"

namespace eyetrace {

struct RetinaSurface {
  double vertex_z_mm = 0.0;  // system frame: z = 0 at the first vertex, +z towards the retina
  double curvature = 0.0;    // 1/mm; < 0 when the centre lies in front (every eye); 0 = flat

  // Largest arc length on the surface the optics library models: a sphere's sequential sheet
  // is the hemisphere on the vertex side, so the retina ends at its equator.
  double max_arc_mm() const { return curvature == 0.0 ? 1e300 : 0.5 * kPiDouble / std::abs(curvature); }
  // (height from the axis, z) of the point at arc length a from the vertex along the meridian.
  glm::dvec2 point(double a) const {
    if (curvature == 0.0) return {a, vertex_z_mm};
    const double phi = curvature * a;
    return {std::sin(phi) / curvature, vertex_z_mm + (1.0 - std::cos(phi)) / curvature};
  }
  // Unit normal at that point, (0, -1) at the vertex: it points out of the retina towards the
  // lens, the side light arrives from; cos(theta) of an arriving ray is measured against it.
  glm::dvec2 normal(double a) const {
    if (curvature == 0.0) return {0.0, -1.0};
    const double phi = curvature * a;
    return {std::sin(phi), -std::cos(phi)};
  }
  // Arc length of the point at lateral height h (h < 1/|c| for a sphere; the near half).
  double arc_for_height(double h) const {
    if (curvature == 0.0) return h;
    return std::asin(std::fmin(1.0, std::abs(curvature) * h)) / std::abs(curvature);
  }
};

// The same points for the per-ray path without a sin/cos call: the angle c a is split into the
// nearest tabulated node angle plus a remainder |delta| <= c h / 2 (h the node spacing), whose
// sine and cosine the Taylor series gives to double precision (|delta| < 1e-3 leaves terms below
// 1e-18).
class RetinaPointTable {
 public:
  RetinaPointTable() = default;
  RetinaPointTable(const RetinaSurface& retina, double max_arc_mm, int nodes = 2048)
      : retina_(retina),
        inv_step_(nodes / std::fmax(max_arc_mm, 1e-9)),
        radius_(retina.curvature == 0.0 ? 0.0 : 1.0 / retina.curvature) {
    for (int i = 0; i <= nodes; ++i) {
      const double phi = retina.curvature * i / inv_step_;
      node_.push_back(static_cast<double>(i) / inv_step_);
      sin_.push_back(std::sin(phi));
      cos_.push_back(std::cos(phi));
    }
  }
  // Point (height, z) and normal of the retina at arc a in [0, max_arc_mm].
  void at(double a, glm::dvec2* point, glm::dvec2* normal) const {
    const double c = retina_.curvature;
    if (c == 0.0) {
      *point = {a, retina_.vertex_z_mm};
      *normal = {0.0, -1.0};
      return;
    }
    const size_t i = std::min(static_cast<size_t>(a * inv_step_ + 0.5), sin_.size() - 1);
    const double delta = c * (a - node_[i]), d2 = delta * delta;
    const double sd = delta * (1.0 - d2 * (1.0 / 6.0) * (1.0 - d2 * (1.0 / 20.0)));
    const double cd = 1.0 - d2 * 0.5 * (1.0 - d2 * (1.0 / 12.0));
    const double s = sin_[i] * cd + cos_[i] * sd, co = cos_[i] * cd - sin_[i] * sd;
    *point = {s * radius_, retina_.vertex_z_mm + (1.0 - co) * radius_};
    *normal = {s, -co};
  }

 private:
  RetinaSurface retina_;
  double inv_step_ = 0.0;
  double radius_ = 0.0;                   // 1 / curvature
  std::vector<double> node_, sin_, cos_;  // node i's arc (i / inv_step_: a load, not a division)
};

}  // namespace eyetrace
