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
  if (name == "bdpt") {
    if (p.get_bool("regularize")) p.warn_param("regularize", "not supported; ignored");
    for (const char* v : {"visualizestrategies", "visualizeweights"})
      if (p.get_bool(v)) p.warn_param(v, "strategy images are not written; ignored");
  }
  return std::make_unique<PathIntegrator>(ctx.scene, p.get_int("maxdepth"), "path");
}

}  // namespace

const PluginSpec& bdpt_integrator_spec() {
  static const PluginSpec spec{"Integrator",
                               "bidirectional path tracing (pbrt-v4): rendered by `path`",
                               kDifference,
                               {param::integer("maxdepth", 5).range(0, 10000).describe("bounces"),
                                param::boolean("regularize", false).describe("`true` warns and is ignored"),
                                param::boolean("visualizestrategies", false).describe("`true` warns and is ignored"),
                                param::boolean("visualizeweights", false).describe("`true` warns and is ignored")}};
  return spec;
}

std::unique_ptr<Integrator> create_bdpt_integrator(const IntegratorContext& ctx) {
  return make_stand_in(ctx, bdpt_integrator_spec(), "bdpt");
}

}  // namespace eyetrace
