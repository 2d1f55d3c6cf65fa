// Material interface: builds the BSDF at a hit, in per-sample scratch memory.
#pragma once
#include "core/arena.h"
#include "core/bsdf.h"
#include "core/interaction.h"

namespace eyetrace {

class Material {
 public:
  virtual ~Material() = default;
  virtual const BSDF* bsdf(const SurfaceInteraction& si, ScratchBuffer& arena) const = 0;
};

}  // namespace eyetrace
