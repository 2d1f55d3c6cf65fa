// Loop subdivision (shapes/loop_subdivision.h) against what does not depend on its code: the
// limit positions are where repeated subdivision converges (the distance to them shrinks
// geometrically with more steps), the limit normals are those of the converged
// surface (pointing against the winding, as pbrt-v4's masks make them), a plane stays a plane
// and a straight boundary stays straight, a regular tetrahedron keeps its symmetry, the
// counts follow Euler's formula, and broken control meshes are refused with the reason.
#include "shapes/loop_subdivision.h"
#include "../support/unity_id.h"

#include <gtest/gtest.h>

#include <cmath>

#include "../support/one_shape.h"
#include "scene/params.h"
#include "shapes/loop_subdiv_mesh.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

const std::vector<Vec3> kTetra = {{1, 1, 1}, {-1, -1, 1}, {-1, 1, -1}, {1, -1, -1}};
const std::vector<int> kTetraFaces = {0, 1, 2, 0, 3, 1, 0, 2, 3, 1, 3, 2};  // counter-clockwise from outside

// A 3 x 3 grid of vertices in z = 0 (2 x 2 quads as 8 triangles, counter-clockwise from +z),
// the middle one lifted to `lift`.
std::vector<Vec3> grid(float lift) {
  std::vector<Vec3> p;
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 3; ++x) p.push_back(Vec3(float(x) - 1.f, float(y) - 1.f, x == 1 && y == 1 ? lift : 0.f));
  return p;
}
const std::vector<int> kGridFaces = {0, 1, 4, 0, 4, 3, 1, 2, 5, 1, 5, 4, 3, 4, 7, 3, 7, 6, 4, 5, 8, 4, 8, 7};

Vec3 winding_normal(const MeshData& m, size_t tri) {
  const Vec3 a = m.positions[size_t(m.indices[tri * 3])], b = m.positions[size_t(m.indices[tri * 3 + 1])],
             c = m.positions[size_t(m.indices[tri * 3 + 2])];
  return glm::normalize(glm::cross(b - a, c - a));
}

TEST(LoopSubdivision, LimitPositionsAndNormalsAreWhereSubdivisionConverges) {
  for (const auto& [p, f] : {std::pair{kTetra, kTetraFaces}, std::pair{grid(0.8f), kGridFaces}}) {
    // Even vertices keep their indices from step to step: vertex v of every mesh is the same
    // point of the surface. Its distance to the claimed limit shrinks by a constant factor
    // (1/16 at the tetrahedron's valence 3, 1/4 around the grid) when the limit is right and
    // levels off when it is not (pbrt-v4's boundary mask 1/5, 3/5, 1/5 stays 0.047 away here).
    const MeshData limit = loop_subdivide(p, f, 1);
    const MeshData m6 = loop_subdivide_without_limit(p, f, 6), m7 = loop_subdivide_without_limit(p, f, 7);
    for (size_t v = 0; v < p.size(); ++v) {
      const float d6 = glm::length(limit.positions[v] - m6.positions[v]);
      const float d7 = glm::length(limit.positions[v] - m7.positions[v]);
      EXPECT_LT(d7, 1e-3f) << v;
      EXPECT_LE(d7, 0.5f * d6 + 1e-6f) << v << ": " << d6 << " then " << d7;
    }
    // The normal is that of the converged surface there: against the winding of the fine
    // triangles around the vertex.
    std::vector<Vec3> around(p.size(), Vec3(0.f));
    for (size_t t = 0; t < m7.indices.size() / 3; ++t)
      for (int k = 0; k < 3; ++k)
        if (size_t v = size_t(m7.indices[t * 3 + size_t(k)]); v < p.size()) around[v] += winding_normal(m7, t);
    for (size_t v = 0; v < p.size(); ++v)
      EXPECT_LT(glm::dot(glm::normalize(limit.normals[v]), glm::normalize(around[v])), -0.99f) << v;
  }
}

TEST(LoopSubdivision, APlaneStaysAPlaneAndAStraightBoundaryStaysStraight) {
  const MeshData m = loop_subdivide(grid(0.f), kGridFaces, 3);
  for (size_t v = 0; v < m.positions.size(); ++v) {
    EXPECT_EQ(m.positions[v].z, 0.f) << v;
    EXPECT_NEAR(glm::normalize(m.normals[v]).z, -1.f, 1e-6f) << v;  // against the +z winding
    // The boundary (the square's edges) stays on the square: nothing leaves [-1, 1]^2.
    EXPECT_LE(std::abs(m.positions[v].x), 1.f + 1e-6f);
    EXPECT_LE(std::abs(m.positions[v].y), 1.f + 1e-6f);
  }
}

TEST(LoopSubdivision, ARegularTetrahedronKeepsItsSymmetryAndEulersCounts) {
  for (int levels : {0, 1, 2, 3}) {
    const MeshData m = loop_subdivide(kTetra, kTetraFaces, levels);
    const size_t faces = m.indices.size() / 3;
    EXPECT_EQ(faces, size_t(4) << (2 * levels));
    EXPECT_EQ(m.positions.size(), 2 + faces / 2);  // V - E + F = 2 with E = 3F/2
    // The four corners stay equidistant from the centre, inside the control tetrahedron's
    // circumsphere (|p| = sqrt 3), as every point does (positive weights: convex combinations).
    const float r0 = glm::length(m.positions[0]);
    for (int v = 1; v < 4; ++v) EXPECT_NEAR(glm::length(m.positions[size_t(v)]), r0, 1e-5f);
    for (const Vec3& p : m.positions) EXPECT_LT(glm::length(p), std::sqrt(3.f) + 1e-5f);
    // The tetrahedron's own limit corner, from its one-ring rule: gamma = 1 / (3 + 3 / (8 * 3/16)) = 1/5,
    // so 2/5 of the corner plus 1/5 of each neighbour: (1,1,1) -> (2/5 - 1/5) (1,1,1).
    if (levels == 0) EXPECT_NEAR(r0, std::sqrt(3.f) / 5.f, 1e-6f);
  }
}

std::string error_of(const std::vector<Vec3>& p, const std::vector<int>& f) {
  try {
    loop_subdivide(p, f, 2);
  } catch (const LoopSubdivisionError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(LoopSubdivision, BrokenControlMeshesAreRefusedWithTheReason) {
  std::vector<Vec3> p = kTetra;
  p.push_back(Vec3(0, 0, 3));
  // A fin: a third triangle on edge (0, 1).
  std::vector<int> fin = kTetraFaces;
  fin.insert(fin.end(), {0, 1, 4});
  EXPECT_NE(error_of(p, fin).find("edge (0, 1) is shared by more than two triangles"), std::string::npos)
      << error_of(p, fin);
  // One triangle wound the other way.
  std::vector<int> flipped = kTetraFaces;
  std::swap(flipped[1], flipped[2]);
  EXPECT_NE(error_of(kTetra, flipped).find("orientations disagree"), std::string::npos) << error_of(kTetra, flipped);
  // Two tetrahedra sharing only vertex 0 (a bow tie there).
  std::vector<Vec3> two = kTetra;
  for (int i = 1; i < 4; ++i) two.push_back(2.f * kTetra[0] - kTetra[size_t(i)]);
  std::vector<int> both = kTetraFaces;
  for (int i : {0, 6, 5, 0, 4, 6, 0, 5, 4, 6, 4, 5}) both.push_back(i);
  EXPECT_NE(error_of(two, both).find("vertex 0 joins separate fans"), std::string::npos) << error_of(two, both);
  EXPECT_NE(error_of(kTetra, {0, 1, 7}).find("out of range"), std::string::npos);
  EXPECT_NE(error_of(kTetra, {0, 1}).find("multiple of 3"), std::string::npos);
  EXPECT_NE(error_of(kTetra, {0, 1, 1}).find("uses vertex 1 twice"), std::string::npos);
  // Unused vertices are dropped, not an error.
  EXPECT_EQ(loop_subdivide(p, kTetraFaces, 0).positions.size(), 4u);
}

TEST(LoopSubdivShape, ErrorsNameFileLineAndParameter) {
  ParameterList pl(SourceLoc{"loop.pbrt", 7, 1});
  Param pp;
  pp.type = "point3";
  pp.name = "P";
  pp.loc = SourceLoc{"loop.pbrt", 7, 20};
  for (const Vec3& v : kTetra) pp.numbers.insert(pp.numbers.end(), {v.x, v.y, v.z});
  pl.add(pp);
  Param pi;
  pi.type = "integer";
  pi.name = "indices";
  pi.loc = SourceLoc{"loop.pbrt", 7, 60};
  pi.numbers = {0, 1, 2, 0, 3, 1, 0, 2, 3, 1, 2, 3};  // the last triangle wound the wrong way
  pl.add(pi);
  const std::string e = test::scene_error_of([&] {
    create_loopsubdiv_shapes(ShapeContext{pl, Transform(), false, "."});
  });
  EXPECT_NE(e.find("loop.pbrt:7:60"), std::string::npos) << e;
  EXPECT_NE(e.find("\"indices\""), std::string::npos) << e;
  EXPECT_NE(e.find("orientations disagree"), std::string::npos) << e;
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
