// Loop subdivision surfaces (Loop 1987), as pbrt-v4's "loopsubdiv" shape makes them: the
// control mesh is subdivided `levels` times (each triangle into four; even vertices moved by
// the one-ring rule with Warren's weights beta = 3/16 for valence 3, 3/(8n) otherwise, the
// crease rule 3/4, 1/8, 1/8 on boundaries; odd vertices at 3/8, 3/8, 1/8, 1/8 of the edge's
// ends and opposite vertices, or the midpoint on a boundary), then every vertex is moved to
// its limit position (one-ring weight 1 / (n + 3 / (8 beta)); on boundaries 2/3, 1/6, 1/6, the
// cubic B-spline's, where pbrt-v4 has 3/5, 1/5, 1/5, which is not the limit) and given the
// limit surface's normal, the cross product of the two limit tangents (pbrt-v4's masks,
// including their orientation: the normals point against the triangles' winding). Vertices
// are numbered by first use in the control indices, then by subdivision.
//
// The control mesh must be a manifold triangle mesh with consistently oriented faces: each
// edge in at most two triangles, traversed in opposite directions by them, and the triangles
// around each vertex a single fan. pbrt-v4 assumes this without checking; eyetrace says which
// triangle or vertex breaks it. Vertices no triangle uses are dropped.
#pragma once
#include <stdexcept>
#include <vector>

#include "shapes/triangle_mesh.h"

namespace eyetrace {

// What is wrong with a control mesh (the caller names the parameter).
class LoopSubdivisionError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Indices are checked (a multiple of 3, in range); `levels` >= 0. The result has positions,
// indices and normals (no uv), in the control mesh's space.
MeshData loop_subdivide(const std::vector<Vec3>& positions, const std::vector<int>& indices, int levels);

// The mesh after `levels` subdivision steps without the push to the limit surface (for tests:
// the limit positions are where repeated subdivision converges).
MeshData loop_subdivide_without_limit(const std::vector<Vec3>& positions, const std::vector<int>& indices, int levels);

}  // namespace eyetrace
