#include "integrators/path_stand_ins.h"

#include "core/diagnostic.h"

namespace eyetrace {

namespace {

const char* kDifference =
    "Rendered by the `path` integrator, with a warning: the same image in expectation (with different noise), "
    "except caustics of point, spot and distant lights seen through specular surfaces, which only light paths "
    "carry.";

std::unique_ptr<Integrator> make_stand_in(const IntegratorContext& ctx, const PluginSpec& spec,
                                          const std::string& name) {
  const PluginParams p(ctx.params, spec, name);
  warn(p.loc(), fmt::format("integrator \"{}\" is rendered by \"path\" (the same image in expectation; caustics of "
                            "point, spot and distant lights through specular surfaces are missed)",
                            name));
  return std::make_unique<PathIntegrator>(ctx.scene, p.get_int("maxdepth"), "path");
}

}  // namespace

const PluginSpec& sppm_integrator_spec() {
  static const PluginSpec spec{
      "Integrator",
      "stochastic progressive photon mapping (pbrt-v4): rendered by `path`",
      kDifference,
      {param::integer("maxdepth", 5).range(0, 10000).describe("bounces"),
       param::integer("photonsperiteration", -1).describe("checked, no effect (no photons are traced)"),
       param::real("radius", 1).above(0).describe("checked, no effect"),
       param::integer("seed", 0).describe("checked, no effect: the render's seed decides")}};
  return spec;
}

std::unique_ptr<Integrator> create_sppm_integrator(const IntegratorContext& ctx) {
  return make_stand_in(ctx, sppm_integrator_spec(), "sppm");
}

}  // namespace eyetrace
