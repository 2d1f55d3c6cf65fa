// A vertex of a bidirectional path tracing subpath (pbrt-v4's BDPT Vertex, surfaces only): the
// camera, a point on a light (or a camera ray that left the scene, which stands for every
// infinite light), or a surface scattering point with its BSDF; its throughput and the
// densities the MIS weights need.
#pragma once
#include "core/bsdf.h"
#include "core/interaction.h"
#include "core/light.h"
#include "core/sampled_spectrum.h"
#include "integrators/bdpt_mis.h"

namespace eyetrace {

enum class BdptVertexType { Camera, Light, Surface };

struct BdptVertex {
  BdptVertexType type = BdptVertexType::Surface;
  SampledSpectrum beta{0.f};
  // Surface vertices: the hit. Endpoints use p, p_error, n (zero off surfaces: cameras, point
  // and spot lights, points at infinity), uv and time.
  SurfaceInteraction si;
  const BSDF* bsdf = nullptr;    // surface vertices
  const Light* light = nullptr;  // light vertices; null: a camera ray that escaped (every infinite light)
  BdptDensities d;

  const Vec3& p() const { return si.p; }
  const Vec3& ng() const { return si.n; }
  const Vec3& ns() const { return type == BdptVertexType::Surface ? si.ns : si.n; }
  bool on_surface() const { return si.n != Vec3(0.f); }
  bool is_light() const { return type == BdptVertexType::Light || (type == BdptVertexType::Surface && si.area_light); }
  bool is_delta_light() const { return type == BdptVertexType::Light && light && light->is_delta(); }
  // Infinite and distant lights: their vertex is a direction, densities per unit solid angle.
  bool is_infinite_light() const {
    return type == BdptVertexType::Light && (!light || light->is_infinite() || light->is_delta_direction());
  }
  // Whether a connection can end here: not on a specular surface, not on a distant light.
  bool connectible() const {
    switch (type) {
      case BdptVertexType::Light: return light && !light->is_delta_direction();
      case BdptVertexType::Camera: return true;
      case BdptVertexType::Surface: return bsdf && (bsdf->flags() & (kDiffuse | kGlossy));
    }
    return false;
  }

  // The BSDF towards `next`. Light-path vertices (importance) take the adjoint BSDF: for a
  // transmission the reversed pair, f(wi, wo), which lacks the radiance-only 1/eta^2 factor of
  // refraction; reflections are symmetric.
  SampledSpectrum f(const BdptVertex& next, bool importance) const {
    Vec3 wi = next.p() - p();
    const float len2 = glm::dot(wi, wi);
    if (!(len2 > 0.f) || !bsdf) return SampledSpectrum(0.f);
    wi /= std::sqrt(len2);
    const bool transmission = glm::dot(wi, si.n) * glm::dot(si.wo, si.n) < 0.f;
    return importance && transmission ? bsdf->f(wi, si.wo) : bsdf->f(si.wo, wi);
  }

  // A solid-angle density from this vertex turned into an area density at `next` (pbrt-v4's
  // ConvertDensity); a point at infinity keeps the solid-angle density.
  float convert_density(float pdf, const BdptVertex& next) const {
    if (next.is_infinite_light()) return pdf;
    const Vec3 w = next.p() - p();
    const float dist2 = glm::dot(w, w);
    if (!(dist2 > 0.f)) return 0.f;
    if (next.on_surface()) pdf *= std::abs(glm::dot(next.ng(), w)) / std::sqrt(dist2);
    return pdf / dist2;
  }
};

}  // namespace eyetrace
