// pbrt-v4's "plymesh": a triangle mesh read from a PLY file (shapes/ply_reader.h). Quads
// (pbrt-v4 would make bilinear patches of them) are triangulated, exact for planar quads.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "scene/registry.h"
#include "shapes/triangle_mesh.h"

namespace eyetrace {

// Reads positions, normals and uvs of every mesh in `path`; errors name the "filename"
// parameter of `params` and the path.
MeshData read_ply_mesh(const std::string& path, const ParameterList& params);

// "string filename" (relative to the scene file's directory). "texture displacement" and
// "float displacement.edgelength"/"edgelength" are warned about: displacement is not
// supported. "alpha" likewise.
const PluginSpec& plymesh_shape_spec();
std::vector<std::unique_ptr<Shape>> create_plymesh_shapes(const ShapeContext& ctx);

}  // namespace eyetrace
