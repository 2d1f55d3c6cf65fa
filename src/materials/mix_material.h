// pbrt-v4's "mix" material: two named materials ("string materials" [a b]) and a float texture
// "amount" (default 0.5). Not a blend of BSDFs: at each hit one of the two is chosen, b where
// amount > u and a otherwise, u a hash of the hit point and the direction to the viewer in
// [0, 1), so a point seen twice from one place is the same material (pbrt-v4's
// MixMaterial::ChooseMaterial). Over a pixel's samples the image is the blend. pbrt-v4 also
// hashes the two materials' addresses, which keeps nested mixes' choices apart; eyetrace hashes
// their names instead, which does the same and is the same from run to run.
#pragma once
#include <cstdint>
#include <memory>

#include "core/material.h"
#include "scene/registry.h"

namespace eyetrace {

const PluginSpec& mix_material_spec();
std::unique_ptr<Material> create_mix_material(const MaterialContext& ctx);

// The hash: uniform in [0, 1) over points, directions and seeds, the same for the same bits.
float mix_material_hash(const Vec3& p, const Vec3& wo, uint64_t seed);

}  // namespace eyetrace
