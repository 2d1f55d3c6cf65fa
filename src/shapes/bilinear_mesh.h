// pbrt-v4's "bilinearmesh": bilinear patches, each split into two triangles. The split is
// exact for planar patches (every parallelogram and every planar quad); a twisted patch is
// approximated by the two triangles that share its p10-p01 diagonal, with a
// crease along that diagonal and a uv mapping that is bilinear only for parallelograms.
#pragma once
#include <memory>
#include <vector>

#include "scene/registry.h"
#include "shapes/triangle_mesh.h"

namespace eyetrace {

// Converts patches (4 indices each, pbrt's order p00 p10 p01 p11) to a triangle mesh.
// Without per-vertex "uv", each patch gets its own four vertices carrying pbrt's patch
// parameterisation (0,0) (1,0) (0,1) (1,1).
MeshData bilinear_patches_to_triangles(const std::vector<Vec3>& positions, const std::vector<int>& quad_indices,
                                       const std::vector<Vec3>& normals, const std::vector<Vec2>& uvs);

// "point3 P", "integer indices" (optional for exactly 4 vertices), "normal N", "point2 uv",
// "integer faceIndices"; "string emissionfilename" is warned about and ignored.
const PluginSpec& bilinearmesh_shape_spec();
std::vector<std::unique_ptr<Shape>> create_bilinearmesh_shapes(const ShapeContext& ctx);

}  // namespace eyetrace
