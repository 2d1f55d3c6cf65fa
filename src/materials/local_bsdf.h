// Turns a BxDF written in a local shading frame (+z = shading normal) into a world-space
// BSDF. Owns the two things every material needs and must not get wrong:
//  - the shading frame, aligned with dpdu so anisotropic roughness follows the surface;
//  - the light-leak guard: a direction pair counts only if the geometric normal and the
//    shading normal agree on whether it is a reflection or a transmission.
// With a normal map the BSDF's shading normal differs from the hit's, which the integrator
// uses for the cosine factor: f is then scaled by |wi.ns_map| / |wi.ns_hit| so that the
// integrator's f |wi.ns_hit| is the mapped BSDF's integrand.
// BxDF requirements: f(wo, wi), sample_f(wo, uc, u) -> optional<BSDFSample> (local wi),
// pdf(wo, wi), flags(); trivially destructible, as the arena never destroys it.
#pragma once
#include <optional>
#include <type_traits>

#include "core/arena.h"
#include "core/bsdf.h"
#include "core/interaction.h"

namespace eyetrace {

inline Frame shading_frame(const SurfaceInteraction& si) {
  Frame f;
  // A degenerate interpolated normal falls back to the geometric one.
  f.n = glm::dot(si.ns, si.ns) > 0.5f ? si.ns : si.n;
  Vec3 s = si.dpdu - f.n * glm::dot(f.n, si.dpdu);
  float len2 = glm::dot(s, s);
  if (!(len2 > 1e-12f) || !std::isfinite(len2)) return Frame(f.n);
  f.s = s / std::sqrt(len2);
  f.t = glm::cross(f.n, f.s);
  return f;
}

template <typename BxDF>
class LocalBSDF final : public BSDF {
  static_assert(std::is_trivially_destructible_v<BxDF>, "BxDFs live in the scratch arena");

 public:
  // `hit_ns`: the shading normal of the hit before any normal map.
  LocalBSDF(const SurfaceInteraction& si, const BxDF& bxdf, const Vec3& hit_ns)
      : frame_(shading_frame(si)), ng_(si.n), hit_ns_(hit_ns), mapped_(hit_ns != si.ns), bxdf_(bxdf) {}

  SampledSpectrum f(const Vec3& wo, const Vec3& wi) const override {
    Vec3 lo = frame_.to_local(wo), li = frame_.to_local(wi);
    if (lo.z == 0.f || !sides_agree(wo, wi, lo, li)) return SampledSpectrum(0.f);
    return bxdf_.f(lo, li) * cosine_ratio(wi, li);
  }

  std::optional<BSDFSample> sample_f(const Vec3& wo, float uc, Vec2 u) const override {
    Vec3 lo = frame_.to_local(wo);
    if (lo.z == 0.f) return std::nullopt;
    std::optional<BSDFSample> s = bxdf_.sample_f(lo, uc, u);
    if (!s || !(s->pdf > 0.f) || s->wi.z == 0.f || !is_finite(s->f) || is_black(s->f)) return std::nullopt;
    Vec3 li = s->wi;
    s->wi = frame_.to_world(li);
    if (!sides_agree(wo, s->wi, lo, li)) return std::nullopt;
    s->f *= cosine_ratio(s->wi, li);
    if (is_black(s->f)) return std::nullopt;
    return s;
  }

  float pdf(const Vec3& wo, const Vec3& wi) const override {
    Vec3 lo = frame_.to_local(wo), li = frame_.to_local(wi);
    if (lo.z == 0.f) return 0.f;
    return bxdf_.pdf(lo, li);
  }

  unsigned flags() const override { return bxdf_.flags(); }
  const BxDF& bxdf() const { return bxdf_; }

 private:
  bool sides_agree(const Vec3& wo, const Vec3& wi, const Vec3& lo, const Vec3& li) const {
    float go = glm::dot(wo, ng_), gi = glm::dot(wi, ng_);
    if (go == 0.f || gi == 0.f) return false;
    return (go * gi > 0.f) == (lo.z * li.z > 0.f);
  }

  float cosine_ratio(const Vec3& wi, const Vec3& li) const {
    if (!mapped_) return 1.f;
    float c = std::abs(glm::dot(wi, hit_ns_));
    return c > 1e-6f ? std::abs(li.z) / c : 0.f;
  }

  Frame frame_;
  Vec3 ng_, hit_ns_;
  bool mapped_;
  BxDF bxdf_;
};

// `si` carries the shading geometry the BSDF uses; `hit_ns` is the hit's own shading normal
// (they differ when a normal map was applied).
template <typename BxDF>
const BSDF* make_local_bsdf(ScratchBuffer& arena, const SurfaceInteraction& si, const BxDF& bxdf, const Vec3& hit_ns) {
  return arena.alloc<LocalBSDF<BxDF>>(si, bxdf, hit_ns);
}

template <typename BxDF>
const BSDF* make_local_bsdf(ScratchBuffer& arena, const SurfaceInteraction& si, const BxDF& bxdf) {
  return make_local_bsdf(arena, si, bxdf, si.ns);
}

}  // namespace eyetrace
