#include "integrators/bdpt_integrator.h"

#include <algorithm>
#include <vector>

#include "core/diagnostic.h"
#include "core/error.h"
#include "core/material.h"
#include "integrators/interface_crossings.h"
#include "integrators/volpath_integrator.h"
#include "render/scene.h"

namespace eyetrace {

struct BdptIntegrator::Walk {
  Sampler& sampler;
  ScratchBuffer& arena;
  RayTally& tally;
  LightSplats* splats = nullptr;  // t = 1 strategies go here; null: none
  // The fewest camera vertices of a strategy used for this sample: 1 when the camera ray can
  // be made by t = 1 too (splats, and the ray lands on the film), else 2.
  int min_t = 2;
};

namespace {

float scene_radius_of(const Scene& scene) {
  const float r = scene.bounds().radius();
  return r > 0.f && std::isfinite(r) ? r : 0.f;
}

BdptVertex endpoint(BdptVertexType type, const Vec3& p, const Vec3& n, const SampledSpectrum& beta, float time) {
  BdptVertex v;
  v.type = type;
  v.beta = beta;
  v.si.p = p;
  v.si.n = n;
  v.si.ns = n;
  v.si.time = time;
  return v;
}

// Scoped overwrite of a value, restored when it goes out of scope (pbrt-v4's ScopedAssignment):
// the MIS weight of one strategy edits the shared subpaths for the duration of its computation.
template <typename T>
class Assign {
 public:
  Assign() = default;
  Assign(T* target, T value) : target_(target), saved_(*target) { *target = value; }
  Assign(const Assign&) = delete;
  Assign& operator=(Assign&& o) noexcept {
    restore();
    target_ = o.target_;
    saved_ = o.saved_;
    o.target_ = nullptr;
    return *this;
  }
  ~Assign() { restore(); }

 private:
  void restore() {
    if (target_) *target_ = saved_;
    target_ = nullptr;
  }
  T* target_ = nullptr;
  T saved_{};
};

}  // namespace

BdptIntegrator::BdptIntegrator(const Scene& scene, int max_depth)
    : Integrator(scene), max_depth_(max_depth), lights_(scene.lights()), scene_radius_(scene_radius_of(scene)) {}

std::string BdptIntegrator::to_string() const {
  return fmt::format("bdpt integrator: maxdepth {}, {} light(s), power light sampling, strategies {}", max_depth_,
                     scene_.lights().size(),
                     light_tracing_ ? "t >= 1 (t = 1 with a camera that has importance)" : "t >= 2");
}

SampledSpectrum BdptIntegrator::radiance(const Ray& ray, SampledWavelengths& lambda, Sampler& sampler,
                                         ScratchBuffer& arena, RayTally& tally, VisibleSurface* visible) const {
  Walk w{sampler, arena, tally};
  return estimate(ray, lambda, w, visible);
}

SampledSpectrum BdptIntegrator::radiance_and_splats(const Ray& ray, SampledWavelengths& lambda, Sampler& sampler,
                                                    ScratchBuffer& arena, RayTally& tally, VisibleSurface* visible,
                                                    LightSplats& splats) const {
  Walk w{sampler, arena, tally, uses_light_splats(splats.camera()) ? &splats : nullptr};
  return estimate(ray, lambda, w, visible);
}

SampledSpectrum BdptIntegrator::estimate(const Ray& ray, SampledWavelengths& lambda, Walk& w,
                                         VisibleSurface* visible) const {
  // pbrt-v4's lengths: a camera subpath of up to maxdepth + 2 vertices (maxdepth bounces plus
  // the camera and a light found at the end), a light subpath of up to maxdepth + 1.
  // Per thread, kept between samples: no allocation per sample once grown.
  thread_local std::vector<BdptVertex> camera_store, light_store;
  camera_store.resize(size_t(max_depth_) + 2);
  light_store.resize(size_t(max_depth_) + 1);
  BdptVertex* camera_path = camera_store.data();
  BdptVertex* light_path = light_store.data();
  const int n_camera = camera_subpath(ray, lambda, w, camera_path, visible);
  const int n_light = light_subpath(lambda, ray.time, w, light_path);
  SampledSpectrum L(0.f);
  // s = 1 samples a light of its own and needs no light subpath, so it runs even when the
  // subpath is empty: a light whose sample_le may find no emission (a projection light's cone
  // outside its image, a goniometric diagram's zeros) would otherwise lose the share of the
  // image its MIS weights give s = 1 (measured: 20 % too dark with a projection light; pbrt-v4
  // loops to nLight and has this bias where its SampleLe fails).
  const int s_max = std::max(n_light, 1);
  for (int t = 2; t <= n_camera; ++t)
    for (int s = 0; s <= s_max; ++s) {
      const int depth = s + t - 2;
      if (depth > max_depth_) break;
      L += connect(lambda, light_path, camera_path, s, t, w);
    }
  // t = 1: a light-path vertex seen by the camera (s = 1 would be a light seen directly,
  // which s = 0 makes, as pbrt-v4 leaves out). connect() splats these.
  if (w.splats)
    for (int s = 2; s <= n_light && s - 1 <= max_depth_; ++s) connect(lambda, light_path, camera_path, s, 1, w);
  return L;
}

int BdptIntegrator::camera_subpath(const Ray& ray, SampledWavelengths& lambda, Walk& w, BdptVertex* path,
                                   VisibleSurface* visible) const {
  path[0] = endpoint(BdptVertexType::Camera, ray.o, Vec3(0.f), SampledSpectrum(1.f), ray.time);
  // The camera's directional density enters only the weights of t = 1 strategies; without
  // them any positive value leaves every weight unchanged. A ray that lands off the film (a
  // wide filter's samples beyond its edge) t = 1 cannot make: its weights leave t = 1 out.
  float pdf_dir = 1.f;
  w.min_t = 2;
  if (w.splats) {
    float pdf_pos = 0.f, dir = 0.f;
    w.splats->camera().pdf_we(ray, &pdf_pos, &dir);
    if (dir > 0.f && std::isfinite(dir)) {
      pdf_dir = dir;
      w.min_t = 1;
    }
  }
  return random_walk(ray, lambda, w, SampledSpectrum(1.f), pdf_dir, max_depth_ + 1, false, path + 1, visible) + 1;
}

int BdptIntegrator::light_subpath(SampledWavelengths& lambda, float time, Walk& w, BdptVertex* path) const {
  float pmf = 0.f;
  const Light* light = lights_.sample(w.sampler.get_1d(), &pmf);
  const Vec2 u1 = w.sampler.get_2d();
  const Vec2 u2 = w.sampler.get_2d();
  if (!light || !(pmf > 0.f)) return 0;
  const std::optional<LightLeSample> les = light->sample_le(u1, u2, lambda, time);
  if (!les || !(les->pdf_pos > 0.f) || !(les->pdf_dir > 0.f) || is_black(les->L)) return 0;
  const float p_l = pmf * les->pdf_pos;
  path[0] = endpoint(BdptVertexType::Light, les->ray.o, les->n, les->L, time);
  path[0].light = light;
  path[0].si.p_error = les->p_error;
  path[0].si.uv = les->uv;
  path[0].d.pdf_fwd = p_l;
  const float cos_light = les->n != Vec3(0.f) ? std::abs(glm::dot(les->n, les->ray.d)) : 1.f;
  const SampledSpectrum beta = les->L * (cos_light / (p_l * les->pdf_dir));
  const int n = random_walk(les->ray, lambda, w, beta, les->pdf_dir, max_depth_, true, path + 1, nullptr);
  if (path[0].is_infinite_light()) {
    // The first hit's density is that of the point on the disc, per unit area across the ray;
    // the light vertex's is the direction's, over every infinite light (pbrt-v4).
    if (n > 0) {
      path[1].d.pdf_fwd = les->pdf_pos;
      if (path[1].on_surface()) path[1].d.pdf_fwd *= std::abs(glm::dot(les->ray.d, path[1].ng()));
    }
    path[0].d.pdf_fwd = infinite_light_density(-les->ray.d);
  }
  return n + 1;
}

int BdptIntegrator::random_walk(Ray ray, SampledWavelengths& lambda, Walk& w, SampledSpectrum beta, float pdf,
                                int max_depth, bool importance, BdptVertex* path, VisibleSurface* visible) const {
  if (max_depth == 0) return 0;
  int bounces = 0;
  float pdf_fwd = pdf;
  for (int crossings = 0; crossings < kMaxInterfaceCrossings && !is_black(beta); ++crossings) {
    BdptVertex& vertex = path[bounces];
    BdptVertex& prev = path[bounces - 1];
    SurfaceInteraction si;
    ++w.tally.rays;
    if (!scene_.intersect(ray, &si)) {
      // A camera ray that leaves the scene ends on the infinite lights, a point at infinity.
      if (!importance) {
        vertex = endpoint(BdptVertexType::Light, ray.o + ray.d, Vec3(0.f), beta, ray.time);
        vertex.d.pdf_fwd = pdf_fwd;
        ++bounces;
      }
      break;
    }
    const BSDF* bsdf = si.material ? si.material->bsdf(si, lambda, w.arena) : nullptr;
    if (!bsdf) {
      ray = spawn_ray(si, ray.d);
      continue;
    }
    if (visible && bounces == 0) *visible = visible_surface(si, *bsdf);
    vertex = BdptVertex{};
    vertex.type = BdptVertexType::Surface;
    vertex.beta = beta;
    vertex.si = si;
    vertex.bsdf = bsdf;
    vertex.d.pdf_fwd = prev.convert_density(pdf_fwd, vertex);
    if (++bounces >= max_depth) break;
    const float uc = w.sampler.get_1d();
    const std::optional<BSDFSample> bs = bsdf->sample_f(si.wo, uc, w.sampler.get_2d());
    if (!bs || !(bs->pdf > 0.f) || is_black(bs->f)) break;
    pdf_fwd = bs->pdf;
    SampledSpectrum f = bs->f;
    // Importance through a refraction lacks radiance's 1/eta^2 (the adjoint BSDF).
    if (importance && (bs->flags & kTransmission)) f *= sqr(bs->eta);
    beta *= f * (std::abs(glm::dot(bs->wi, si.ns)) / bs->pdf);
    if (!is_finite(beta)) break;
    float pdf_rev = bsdf->pdf(bs->wi, si.wo);
    if (bs->is_specular()) {
      vertex.d.delta = true;
      pdf_rev = pdf_fwd = 0.f;
    }
    prev.d.pdf_rev = vertex.convert_density(pdf_rev, prev);
    ray = spawn_ray(si, bs->wi);
  }
  return bounces;
}

bool BdptIntegrator::unoccluded(const BdptVertex& a, const BdptVertex& b, Walk& w) const {
  ++w.tally.rays;
  ++w.tally.shadow_rays;
  return !scene_.occluded(spawn_ray_to(a.si.p, a.si.p_error, a.si.n, a.si.time, b.si.p, b.si.p_error, b.si.n));
}

SampledSpectrum BdptIntegrator::emitted(const BdptVertex& v, const BdptVertex& towards,
                                        const SampledWavelengths& lambda) const {
  if (!v.is_light()) return SampledSpectrum(0.f);
  Vec3 dir = towards.p() - v.p();
  const float len2 = glm::dot(dir, dir);
  if (!(len2 > 0.f)) return SampledSpectrum(0.f);
  dir /= std::sqrt(len2);
  if (v.is_infinite_light()) {
    SampledSpectrum Le(0.f);
    for (const Light* light : scene_.infinite_lights()) Le += light->Le(Ray{v.p(), -dir}, lambda);
    return Le;
  }
  return v.si.area_light ? v.si.area_light->L(v.si, dir, lambda) : SampledSpectrum(0.f);
}

float BdptIntegrator::infinite_light_density(const Vec3& to_light) const {
  float pdf = 0.f;
  for (const Light* light : scene_.infinite_lights())
    pdf += light->pdf_li(LightSampleContext{}, to_light, nullptr) * lights_.pmf(light);
  return pdf;
}

float BdptIntegrator::pdf_light(const BdptVertex& lv, const BdptVertex& next) const {
  Vec3 w = next.p() - lv.p();
  const float dist2 = glm::dot(w, w);
  if (!(dist2 > 0.f)) return 0.f;
  w /= std::sqrt(dist2);
  float pdf = 0.f;
  if (lv.is_infinite_light()) {
    // Density of the point on the disc through which the ray from infinity passes.
    pdf = scene_radius_ > 0.f ? 1.f / (kPi * sqr(scene_radius_)) : 0.f;
  } else {
    const Light* light = lv.type == BdptVertexType::Light ? lv.light : lv.si.area_light;
    float pdf_pos = 0.f, pdf_dir = 0.f;
    light->pdf_le(lv.p(), lv.ng(), w, &pdf_pos, &pdf_dir);
    pdf = pdf_dir / dist2;
  }
  if (next.on_surface()) pdf *= std::abs(glm::dot(next.ng(), w));
  return pdf;
}

float BdptIntegrator::pdf_light_origin(const BdptVertex& lv, const BdptVertex& next) const {
  Vec3 w = next.p() - lv.p();
  const float len2 = glm::dot(w, w);
  if (!(len2 > 0.f)) return 0.f;
  w /= std::sqrt(len2);
  if (lv.is_infinite_light()) return infinite_light_density(-w);
  const Light* light = lv.type == BdptVertexType::Light ? lv.light : lv.si.area_light;
  float pdf_pos = 0.f, pdf_dir = 0.f;
  light->pdf_le(lv.p(), lv.ng(), w, &pdf_pos, &pdf_dir);
  return pdf_pos * lights_.pmf(light);
}

float BdptIntegrator::pdf(const BdptVertex& v, const BdptVertex* prev, const BdptVertex& next,
                          const Camera* camera) const {
  if (v.type == BdptVertexType::Light) return pdf_light(v, next);
  if (v.type == BdptVertexType::Camera) {
    // The camera's directional density (t = 1 strategies only).
    Vec3 wn = next.p() - v.p();
    const float ln = glm::dot(wn, wn);
    if (!camera || !(ln > 0.f)) return 0.f;
    float pdf_pos = 0.f, pdf_dir = 0.f;
    camera->pdf_we(Ray{v.p(), wn / std::sqrt(ln), kInfinity, v.si.time}, &pdf_pos, &pdf_dir);
    return v.convert_density(pdf_dir, next);
  }
  if (v.type != BdptVertexType::Surface || !prev) return 0.f;
  Vec3 wn = next.p() - v.p(), wp = prev->p() - v.p();
  const float ln = glm::dot(wn, wn), lp = glm::dot(wp, wp);
  if (!(ln > 0.f) || !(lp > 0.f)) return 0.f;
  return v.convert_density(v.bsdf->pdf(wp / std::sqrt(lp), wn / std::sqrt(ln)), next);
}

SampledSpectrum BdptIntegrator::connect(const SampledWavelengths& lambda, BdptVertex* light_path,
                                        BdptVertex* camera_path, int s, int t, Walk& w) const {
  BdptVertex& pt = camera_path[t - 1];
  // A camera path that ended on the infinite lights connects to nothing.
  if (s != 0 && pt.type == BdptVertexType::Light) return SampledSpectrum(0.f);
  SampledSpectrum L(0.f);
  BdptVertex sampled;
  Vec2 p_raster(0.f);
  if (t == 1) {
    // A point on the lens sampled from a light-path vertex (pbrt-v4's t = 1 branch).
    const BdptVertex& qs = light_path[s - 1];
    const Vec2 u = w.sampler.get_2d();
    if (!qs.connectible()) return L;
    const std::optional<CameraWiSample> cs = w.splats->camera().sample_wi(qs.p(), qs.si.time, u);
    if (!cs) return L;
    p_raster = cs->p_raster;
    sampled = endpoint(BdptVertexType::Camera, cs->p_lens, cs->n_lens, SampledSpectrum(cs->Wi / cs->pdf), qs.si.time);
    L = qs.beta * qs.f(sampled, true) * sampled.beta;
    if (qs.on_surface()) L *= std::abs(glm::dot(cs->wi, qs.ns()));
    if (is_black(L) || !is_finite(L) || !unoccluded(qs, sampled, w)) return SampledSpectrum(0.f);
    w.splats->add(p_raster, L * mis_weight(light_path, camera_path, sampled, s, t, w), lambda);
    return SampledSpectrum(0.f);
  }
  if (s == 0) {
    // The camera path found an emitter.
    L = emitted(pt, camera_path[t - 2], lambda) * pt.beta;
  } else if (s == 1) {
    // A point on a light sampled from pt (next-event estimation).
    if (!pt.connectible()) return L;
    float pmf = 0.f;
    const Light* light = lights_.sample(w.sampler.get_1d(), &pmf);
    const Vec2 u = w.sampler.get_2d();
    if (!light || !(pmf > 0.f)) return L;
    const std::optional<LightLiSample> ls = light->sample_li(LightSampleContext{pt.si.p, pt.si.n}, u, lambda);
    if (!ls || !(ls->pdf > 0.f) || is_black(ls->L)) return L;
    // Infinite and distant lights' points stand for directions: no surface there (pbrt-v4).
    const bool at_infinity = light->is_infinite() || light->is_delta_direction();
    sampled = endpoint(BdptVertexType::Light, ls->p_light, at_infinity ? Vec3(0.f) : ls->n_light,
                       ls->L / (ls->pdf * pmf), pt.si.time);
    sampled.light = light;
    sampled.si.p_error = ls->p_light_error;
    sampled.d.pdf_fwd = pdf_light_origin(sampled, pt);
    L = pt.beta * pt.f(sampled, false) * sampled.beta * std::abs(glm::dot(ls->wi, pt.ns()));
    if (is_black(L) || !unoccluded(pt, sampled, w)) return SampledSpectrum(0.f);
  } else {
    // A light-path vertex joined to a camera-path vertex.
    const BdptVertex& qs = light_path[s - 1];
    if (!qs.connectible() || !pt.connectible()) return L;
    L = qs.beta * qs.f(pt, true) * pt.f(qs, false) * pt.beta;
    if (is_black(L)) return L;
    Vec3 d = qs.p() - pt.p();
    float g = 1.f / glm::dot(d, d);
    d *= std::sqrt(g);
    if (qs.on_surface()) g *= std::abs(glm::dot(qs.ns(), d));
    if (pt.on_surface()) g *= std::abs(glm::dot(pt.ns(), d));
    if (!(g > 0.f) || !std::isfinite(g)) return SampledSpectrum(0.f);
    L *= g;
    if (!unoccluded(pt, qs, w)) return SampledSpectrum(0.f);
  }
  if (is_black(L) || !is_finite(L)) return SampledSpectrum(0.f);
  return L * mis_weight(light_path, camera_path, sampled, s, t, w);
}

float BdptIntegrator::mis_weight(BdptVertex* light_path, BdptVertex* camera_path, const BdptVertex& sampled, int s,
                                 int t, const Walk& w) const {
  if (s + t == 2) return 1.f;
  BdptVertex* qs = s > 0 ? &light_path[s - 1] : nullptr;
  BdptVertex* pt = &camera_path[t - 1];
  BdptVertex* qs_minus = s > 1 ? &light_path[s - 2] : nullptr;
  BdptVertex* pt_minus = t > 1 ? &camera_path[t - 2] : nullptr;
  const Camera* camera = w.splats ? &w.splats->camera() : nullptr;
  // The strategy's own connection: its vertices as this strategy made them, then the reverse
  // densities that only the connection defines (pbrt-v4's a1 ... a7).
  Assign<BdptVertex> a1;
  if (s == 1) a1 = Assign<BdptVertex>(qs, sampled);
  if (t == 1) a1 = Assign<BdptVertex>(pt, sampled);
  Assign<bool> a2(&pt->d.delta, false), a3;
  if (qs) a3 = Assign<bool>(&qs->d.delta, false);
  Assign<float> a4(&pt->d.pdf_rev, s > 0 ? pdf(*qs, qs_minus, *pt) : pdf_light_origin(*pt, *pt_minus));
  Assign<float> a5;
  if (pt_minus) a5 = Assign<float>(&pt_minus->d.pdf_rev, s > 0 ? pdf(*pt, qs, *pt_minus) : pdf_light(*pt, *pt_minus));
  Assign<float> a6, a7;
  if (qs) a6 = Assign<float>(&qs->d.pdf_rev, pdf(*pt, pt_minus, *qs, camera));
  if (qs_minus) a7 = Assign<float>(&qs_minus->d.pdf_rev, pdf(*qs, pt, *qs_minus));

  thread_local std::vector<BdptDensities> cam, lig;
  cam.resize(size_t(t));
  lig.resize(size_t(s));
  for (int i = 0; i < t; ++i) cam[size_t(i)] = camera_path[i].d;
  for (int i = 0; i < s; ++i) lig[size_t(i)] = light_path[i].d;
  const bool delta_light = s > 0 && light_path[0].is_delta_light();
  return bdpt_mis_weight(cam.data(), t, lig.data(), s, delta_light, w.min_t);
}

const PluginSpec& bdpt_integrator_spec() {
  static const PluginSpec spec{
      "Integrator",
      "bidirectional path tracing (pbrt-v4's algorithm and MIS weights), surfaces",
      "Strategies t = 1 (light paths connected to the lens, splatted) with the perspective camera only; other "
      "cameras, `--adaptive` and several MPI processes take t >= 2 alone, which miss a caustic of a point, spot or "
      "distant light on a diffuse surface seen directly (as `path` does). Scenes with participating media are rendered "
      "by `volpath`, with a warning. Infinite lights with a portal "
      "are refused. Rough refraction at light-path vertices takes the adjoint BSDF "
      "by reversing the pair.",
      {param::integer("maxdepth", 5).range(0, 10000).describe("bounces"),
       param::boolean("lighttracing", true)
           .describe("eyetrace's (not pbrt-v4's): `false` leaves out the t = 1 strategies"),
       param::boolean("regularize", false).describe("`true` warns and is ignored"),
       param::boolean("visualizestrategies", false).describe("`true` warns and is ignored"),
       param::boolean("visualizeweights", false).describe("`true` warns and is ignored")}};
  return spec;
}

std::unique_ptr<Integrator> create_bdpt_integrator(const IntegratorContext& ctx) {
  const PluginParams p(ctx.params, bdpt_integrator_spec(), "bdpt");
  if (p.get_bool("regularize")) p.warn_param("regularize", "not supported; ignored");
  for (const char* v : {"visualizestrategies", "visualizeweights"})
    if (p.get_bool(v)) p.warn_param(v, "strategy images are not written; ignored");
  const int max_depth = p.get_int("maxdepth");
  if (ctx.scene.has_media()) {
    warn(p.loc(), "integrator \"bdpt\" does not trace participating media: the scene is rendered by \"volpath\"");
    return std::make_unique<VolPathIntegrator>(ctx.scene, max_depth, RussianRoulette{});
  }
  for (const Light* light : ctx.scene.lights())
    if (!light->emits_rays())
      throw SceneError(Diagnostic{p.loc(), "", Severity::Error,
                                  "integrator \"bdpt\" cannot start light paths from an infinite light seen through a "
                                  "portal; use \"path\" or \"volpath\""});
  auto bdpt = std::make_unique<BdptIntegrator>(ctx.scene, max_depth);
  bdpt->set_light_tracing(p.get_bool("lighttracing"));
  return bdpt;
}

}  // namespace eyetrace
