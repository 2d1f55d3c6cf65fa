#include "materials/interface_material.h"

namespace eyetrace {

namespace {

class InterfaceMaterial final : public Material {
 public:
  const BSDF* bsdf(const SurfaceInteraction&, SampledWavelengths&, ScratchBuffer&) const override { return nullptr; }
};

}  // namespace

const PluginSpec& interface_material_spec() {
  static const PluginSpec spec{"Material", "no surface: a boundary between media (rays pass through)", "—", {}};
  return spec;
}

std::unique_ptr<Material> create_interface_material(const MaterialContext& ctx) {
  PluginParams(ctx.params, interface_material_spec(), "interface");
  return std::make_unique<InterfaceMaterial>();
}

}  // namespace eyetrace
