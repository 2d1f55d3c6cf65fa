// Meshes made in code rather than read from a scene: a UV sphere for benchmarks and tests
// (2 * segments * (rings - 1) triangles, e.g. rings 200 x segments 256 = 101,888).
#pragma once
#include <memory>
#include <vector>

#include "core/math.h"
#include "shapes/triangle_mesh.h"

namespace eyetrace {

struct ProceduralMesh {
  std::vector<Vec3> positions;
  std::vector<int> indices;   // 3 per triangle, counter-clockwise seen from outside
  std::vector<Vec3> normals;  // unit, outward (the exact sphere normals at the vertices)
};

// A sphere of `radius` about the origin: `rings` latitude bands (>= 2) between the poles,
// `segments` longitude slices (>= 3). Poles are single vertices, so the triangle count is
// 2 * segments * (rings - 1) and the vertex count segments * (rings - 1) + 2. Outward
// triangle normals cross(p0 - p2, p1 - p2) (pbrt's convention). Throws std::invalid_argument
// on too few rings or segments.
ProceduralMesh make_uv_sphere_mesh(int rings, int segments, float radius = 1.f);

// The mesh as a renderable shape (with its vertex normals as shading normals).
std::unique_ptr<TriangleMesh> make_triangle_mesh(const ProceduralMesh& mesh,
                                                 const Transform& world_from_object = Transform());

}  // namespace eyetrace
