#include "core/visible_surface.h"

#include "core/bsdf.h"
#include "core/interaction.h"

namespace eyetrace {

namespace {
constexpr int kRhoSamples = 16;
// pbrt-v4's ucRho and uRho, number for number.
constexpr float kUcRho[kRhoSamples] = {0.75741637f, 0.37870818f, 0.7083487f, 0.18935409f, 0.9149363f, 0.35417435f,
                                       0.5990858f,  0.09467703f, 0.8578725f, 0.45746812f, 0.686759f,  0.17708716f,
                                       0.9674518f,  0.2995429f,  0.5083201f, 0.047338516f};
constexpr float kURho[kRhoSamples][2] = {
    {0.855985f, 0.570367f}, {0.381823f, 0.851844f}, {0.285328f, 0.764262f}, {0.733380f, 0.114073f},
    {0.542663f, 0.344465f}, {0.127274f, 0.414848f}, {0.964700f, 0.947162f}, {0.594089f, 0.643463f},
    {0.095109f, 0.170369f}, {0.825444f, 0.263359f}, {0.429467f, 0.454469f}, {0.244460f, 0.816459f},
    {0.756135f, 0.731258f}, {0.516165f, 0.152852f}, {0.180888f, 0.214174f}, {0.898579f, 0.503897f}};

Vec3 face_forward(const Vec3& n, const Vec3& w) { return glm::dot(n, w) < 0.f ? -n : n; }
}  // namespace

VisibleSurface visible_surface(const SurfaceInteraction& si, const BSDF& bsdf) {
  VisibleSurface v;
  v.set = true;
  v.p = si.p;
  v.n = face_forward(si.n, si.wo);
  v.ns = face_forward(si.ns, si.wo);
  v.uv = si.uv;
  v.time = si.time;
  // rho(wo) = E[f |cos| / pdf] over the BSDF's own sampling; a sample that fails counts 0.
  SampledSpectrum rho(0.f);
  for (int i = 0; i < kRhoSamples; ++i) {
    const std::optional<BSDFSample> bs = bsdf.sample_f(si.wo, kUcRho[i], Vec2(kURho[i][0], kURho[i][1]));
    if (bs && bs->pdf > 0.f) rho += bs->f * (std::abs(glm::dot(bs->wi, si.ns)) / bs->pdf);
  }
  v.albedo = rho / float(kRhoSamples);
  return v;
}

}  // namespace eyetrace
