#include "integrators/path_integrator.h"

#include <algorithm>

#include "core/material.h"
#include "core/sampling.h"
#include "integrators/direct_light_sample.h"
#include "integrators/subsurface_exit.h"
#include "integrators/volpath_integrator.h"
#include "render/scene.h"

namespace eyetrace {

PathIntegrator::PathIntegrator(const Scene& scene, int max_depth, std::string name, RussianRoulette roulette)
    : Integrator(scene),
      max_depth_(max_depth),
      name_(std::move(name)),
      roulette_(roulette),
      lights_(scene.lights()),
      hittable_lights_(
          std::any_of(scene.lights().begin(), scene.lights().end(), [](const auto& l) { return !l->is_delta(); })) {}

std::string PathIntegrator::to_string() const {
  return fmt::format("{} integrator: maxdepth {}, {} light(s), power light sampling", name_, max_depth_,
                     scene_.lights().size());
}

bool PathIntegrator::continue_from_subsurface_exit(const SurfaceInteraction& entry, const BSSRDF& bssrdf,
                                                   SampledWavelengths& lambda, Sampler& sampler, ScratchBuffer& arena,
                                                   RayTally& tally, SampledSpectrum& beta, SampledSpectrum& L, Ray& ray,
                                                   float& prev_bsdf_pdf, LightSampleContext& prev_ctx) const {
  const std::optional<SubsurfaceExit> exit =
      sample_subsurface_exit(scene_, bssrdf, entry, lambda, sampler, arena, tally);
  if (!exit) return false;
  beta *= exit->weight(lambda);
  // Next-event estimation at the exit, MIS-weighted against sampling Sw (as at any surface).
  if (!lights_.empty())
    L += beta * sample_one_light(scene_, lights_, exit->si, *exit->sw, lambda, sampler, tally);
  else
    ++tally.shadow_rays_skipped;
  const float uc = sampler.get_1d();
  const std::optional<BSDFSample> ws = exit->sw->sample_f(exit->si.wo, uc, sampler.get_2d());
  if (!ws || !(ws->pdf > 0.f) || is_black(ws->f)) return false;
  beta *= ws->f * std::abs(glm::dot(ws->wi, exit->si.ns)) / ws->pdf;
  prev_bsdf_pdf = ws->pdf;
  prev_ctx = LightSampleContext{exit->si.p, exit->si.n};
  ray = spawn_ray(exit->si, ws->wi);
  return is_finite(beta);
}

SampledSpectrum PathIntegrator::radiance(const Ray& camera_ray, SampledWavelengths& lambda, Sampler& sampler,
                                         ScratchBuffer& arena, RayTally& tally, VisibleSurface* visible) const {
  SampledSpectrum L(0.f), beta(1.f);
  Ray ray = camera_ray;
  bool specular_bounce = false;
  float prev_bsdf_pdf = 0.f;
  LightSampleContext prev_ctx;
  int depth = 0;
  // Interface (null-material) crossings do not count as bounces; bound them anyway so a
  // degenerate scene cannot loop forever.
  for (int crossings = 0; crossings < 256; ++crossings) {
    SurfaceInteraction si;
    ++tally.rays;
    bool hit = scene_.intersect(ray, &si);
    // Emission seen by the BSDF-sampled ray, weighted against light sampling (MIS).
    auto add_emission = [&](const Light* light, const SampledSpectrum& Le, const SurfaceInteraction* at) {
      if (is_black(Le)) return;
      if (depth == 0 || specular_bounce) {
        L += beta * Le;
        return;
      }
      float light_pdf = lights_.pmf(light) * light->pdf_li(prev_ctx, ray.d, at);
      L += beta * Le * power_heuristic(prev_bsdf_pdf, light_pdf);
    };
    if (!hit) {
      for (const Light* light : scene_.infinite_lights()) add_emission(light, light->Le(ray, lambda), nullptr);
      break;
    }
    if (si.area_light) add_emission(si.area_light, si.area_light->L(si, -ray.d, lambda), &si);
    const BSDF* bsdf = si.material ? si.material->bsdf(si, lambda, arena) : nullptr;
    if (!bsdf) {
      ray = spawn_ray(si, ray.d);
      continue;
    }
    if (visible && depth == 0) *visible = visible_surface(si, *bsdf);
    if (depth++ == max_depth_) break;
    if (!lights_.empty() && (bsdf->flags() & (kDiffuse | kGlossy)))
      L += beta * sample_one_light(scene_, lights_, si, *bsdf, lambda, sampler, tally);
    else
      ++tally.shadow_rays_skipped;  // no light to sample, or a specular BSDF that light sampling cannot hit
    // The next ray could only add emission it finds, and there is none to find (unless it
    // refracts into a subsurface material, whose exit point samples light as pbrt-v4 does).
    if (depth == max_depth_ && !hittable_lights_ && !si.material->has_subsurface()) break;

    float uc = sampler.get_1d();
    std::optional<BSDFSample> bs = bsdf->sample_f(si.wo, uc, sampler.get_2d());
    if (!bs || bs->pdf <= 0.f || is_black(bs->f)) break;
    beta *= bs->f * std::abs(glm::dot(bs->wi, si.ns)) / bs->pdf;
    specular_bounce = bs->is_specular();
    prev_bsdf_pdf = bs->pdf;
    prev_ctx = LightSampleContext{si.p, si.n};
    ray = spawn_ray(si, bs->wi);
    if (!is_finite(beta)) break;
    // Light refracted into a subsurface material leaves elsewhere: the path continues from the
    // exit point instead (no bounce counted, as pbrt-v4).
    const BSSRDF* bssrdf =
        (bs->flags & kTransmission) && si.material->has_subsurface() ? si.material->bssrdf(si, lambda, arena) : nullptr;
    if (bssrdf) {
      if (!continue_from_subsurface_exit(si, *bssrdf, lambda, sampler, arena, tally, beta, L, ray, prev_bsdf_pdf,
                                         prev_ctx))
        break;
      specular_bounce = false;  // the path leaves through Sw, a diffuse lobe
    }
    // Russian roulette on the throughput (russian_roulette.h).
    if (roulette_.terminates(depth, RussianRoulette::weight(beta, lambda), sampler, beta)) break;
  }
  return L;
}

namespace {

PluginSpec make_path_spec(int default_depth, const std::string& summary, const std::string& differences) {
  return PluginSpec{"Integrator",
                    summary,
                    differences,
                    {param::integer("maxdepth", default_depth).range(0, 10000).describe("bounces"),
                     param::string("lightsampler", "bvh")
                         .in({"bvh", "power", "uniform"})
                         .describe("eyetrace always samples lights in proportion to their power"),
                     param::boolean("regularize", false).describe("`true` warns and is ignored"),
                     param::real("rrthreshold", 1)
                         .at_least(0)
                         .describe("Russian roulette where the path throughput's largest component is below it "
                                   "(pbrt-v3 and early pbrt-v4; today's pbrt-v4 refuses it and uses 1)"),
                     param::integer("rrdepth", RussianRoulette{}.from_depth)
                         .range(1, 1 << 30)
                         .describe("eyetrace's: the first scattering vertex that plays Russian roulette (Mitsuba 3's "
                                   "rr_depth; pbrt-v4 plays from the second, `rrdepth 2`)")}};
}

struct PathParams {
  int max_depth;
  RussianRoulette roulette;
};

// The options pbrt-v4's path integrators share; eyetrace has one light sampler.
PathParams read_path_params(const IntegratorContext& ctx, const PluginSpec& spec, const std::string& name) {
  const PluginParams p(ctx.params, spec, name);
  // pbrt-v4's default "bvh" is unbiased like ours; only an explicit request is worth a note.
  const std::string ls = p.get_string("lightsampler");
  if (p.has("lightsampler") && ls != "power")
    warn(p.loc(), fmt::format("lightsampler \"{}\": eyetrace samples lights by power", ls));
  if (p.get_bool("regularize")) warn(p.loc(), "\"regularize\" is not supported; ignored");
  return {p.get_int("maxdepth"), RussianRoulette{p.get_float("rrthreshold"), p.get_int("rrdepth")}};
}

std::unique_ptr<Integrator> make_path(const IntegratorContext& ctx, const PluginSpec& spec, const std::string& name,
                                      const std::string& renders_as) {
  const PathParams p = read_path_params(ctx, spec, name);
  return std::make_unique<PathIntegrator>(ctx.scene, p.max_depth, renders_as, p.roulette);
}

}  // namespace

const PluginSpec& path_integrator_spec() {
  static const PluginSpec spec = make_path_spec(
      5, "unidirectional path tracing with next-event estimation and multiple importance sampling",
      "Lights are always sampled in proportion to their power; asking for `bvh` or `uniform` explicitly warns. "
      "`regularize` true warns and is ignored. Russian roulette starts at the fifth scattering vertex, not the second "
      "(`rrdepth`, eyetrace's own; `rrdepth 2` plays as pbrt-v4).");
  return spec;
}

const PluginSpec& volpath_integrator_spec() {
  static const PluginSpec spec =
      make_path_spec(5,
                     "`path` with participating media (spectral MIS, Henyey-Greenstein scattering; delta tracking "
                     "through grid media's majorants)",
                     "Russian roulette as `path` (from the fifth vertex, `rrdepth`). Shadow rays carry the exact "
                     "transmittance of homogeneous media (pbrt-v4 ratio-tracks it; "
                     "heterogeneous ones are ratio-tracked as pbrt-v4); a scene without media is rendered by `path`, "
                     "which then gives the same image.");
  return spec;
}

const PluginSpec& direct_integrator_spec() {
  static const PluginSpec spec = make_path_spec(1, "direct lighting: the path estimator stopped after the first bounce",
                                                "eyetrace's own; pbrt-v4 has no `direct`.");
  return spec;
}

std::unique_ptr<Integrator> create_path_integrator(const IntegratorContext& ctx) {
  return make_path(ctx, path_integrator_spec(), "path", "path");
}

std::unique_ptr<Integrator> create_direct_integrator(const IntegratorContext& ctx) {
  return make_path(ctx, direct_integrator_spec(), "direct", "direct");
}

std::unique_ptr<Integrator> create_volpath_integrator(const IntegratorContext& ctx) {
  // Without media volpath's estimator is path's: the same code renders it, at the same speed.
  if (!ctx.scene.has_media()) return make_path(ctx, volpath_integrator_spec(), "volpath", "volpath");
  const PathParams p = read_path_params(ctx, volpath_integrator_spec(), "volpath");
  return std::make_unique<VolPathIntegrator>(ctx.scene, p.max_depth, p.roulette);
}

}  // namespace eyetrace
