#include "materials/interface_material.h"

namespace eyetrace {

namespace {

class InterfaceMaterial final : public Material {
 public:
  const BSDF* bsdf(const SurfaceInteraction&, ScratchBuffer&) const override { return nullptr; }
};

}  // namespace

std::unique_ptr<Material> create_interface_material(const MaterialContext&) {
  return std::make_unique<InterfaceMaterial>();
}

}  // namespace eyetrace
