// pbrt-v4's "loopsubdiv" shape: a triangle control mesh ("P", "indices") refined by Loop
// subdivision "levels" times (shapes/loop_subdivision.h) and rendered as the triangle mesh of
// its limit positions and normals.
#pragma once
#include <memory>
#include <vector>

#include "core/shape.h"
#include "scene/registry.h"

namespace eyetrace {

const PluginSpec& loopsubdiv_shape_spec();
std::vector<std::unique_ptr<Shape>> create_loopsubdiv_shapes(const ShapeContext& ctx);

}  // namespace eyetrace
