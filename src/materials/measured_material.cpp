#include "materials/measured_material.h"

#include <filesystem>

#include "materials/local_bsdf.h"
#include "materials/measured_bxdf.h"
#include "materials/shading_normal.h"
#include "scene/scene_files.h"

namespace eyetrace {

namespace {

class MeasuredMaterial final : public Material {
 public:
  MeasuredMaterial(std::shared_ptr<const MeasuredBRDF> brdf, ShadingNormal shading)
      : brdf_(std::move(brdf)), shading_(shading) {}

  const BSDF* bsdf(const SurfaceInteraction& hit, SampledWavelengths& lambda, ScratchBuffer& arena) const override {
    SurfaceInteraction si = shading_.apply(hit);
    return make_local_bsdf(arena, si, MeasuredBxDF(brdf_.get(), lambda), hit.ns);
  }

 private:
  std::shared_ptr<const MeasuredBRDF> brdf_;
  ShadingNormal shading_;
};

}  // namespace

const PluginSpec& measured_material_spec() {
  static const PluginSpec spec{
      "Material", "a measured BRDF of the RGL material database (a tensor `.bsdf` file)",
      "Files with an `rgb` field instead of `spectra` are refused (pbrt-v4 aborts on them). Where the file's "
      "visible-normal table has no density, f is 0 (pbrt-v4 computes NaN there).",
      std::vector<ParamSpec>{param::string("filename")
                                 .shown_default("required")
                                 .describe("RGL tensor file: spectral (`spectra` + `wavelengths`), isotropic or "
                                           "anisotropic; read once per file")} +
          ShadingNormal::declared()};
  return spec;
}

std::unique_ptr<Material> create_measured_material(const MaterialContext& ctx) {
  const PluginParams p(ctx.params, measured_material_spec(), "measured");
  if (!p.has("filename")) p.fail("filename", "a measured BRDF file (.bsdf) is required");
  const std::string path = resolve_scene_file(ctx.search_dir, p.get_string("filename"));
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    p.fail_missing_file("filename", fmt::format("cannot open \"{}\": no such file", path));
  std::shared_ptr<const MeasuredBRDF> brdf;
  try {
    brdf = load_measured_brdf(path);
  } catch (const TensorFileError& e) {
    p.fail("filename", fmt::format("\"{}\": {}", path, e.what()));
  }
  return std::make_unique<MeasuredMaterial>(std::move(brdf), ShadingNormal::read(ctx, p));
}

}  // namespace eyetrace
