// The UV-sphere benchmark mesh: triangle counts by construction, outward winding, and
// convergence of its area to the sphere's 4 pi r^2.
#include "shapes/procedural_mesh.h"
#include "../support/unity_id.h"

#include <gtest/gtest.h>

#include "shapes/triangle_mesh.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

double mesh_area(const ProceduralMesh& m) {
  double area = 0.0;
  for (size_t i = 0; i < m.indices.size(); i += 3) {
    glm::dvec3 a(m.positions[m.indices[i]]), b(m.positions[m.indices[i + 1]]), c(m.positions[m.indices[i + 2]]);
    area += 0.5 * glm::length(glm::cross(b - a, c - a));
  }
  return area;
}

TEST(ProceduralMesh, UVSphereCounts) {
  ProceduralMesh m = make_uv_sphere_mesh(200, 256);
  EXPECT_EQ(m.indices.size() / 3, size_t(2 * 256 * 199));  // 101,888 >= 100k
  EXPECT_EQ(m.positions.size(), size_t(256 * 199 + 2));
  EXPECT_EQ(m.normals.size(), m.positions.size());
  for (int i : m.indices) ASSERT_TRUE(i >= 0 && size_t(i) < m.positions.size());
  EXPECT_THROW(make_uv_sphere_mesh(1, 8), std::invalid_argument);
  EXPECT_THROW(make_uv_sphere_mesh(4, 2), std::invalid_argument);
}

TEST(ProceduralMesh, UVSphereWindsOutward) {
  ProceduralMesh m = make_uv_sphere_mesh(12, 16, 2.f);
  for (size_t i = 0; i < m.indices.size(); i += 3) {
    Vec3 p0 = m.positions[m.indices[i]], p1 = m.positions[m.indices[i + 1]], p2 = m.positions[m.indices[i + 2]];
    Vec3 n = glm::cross(p0 - p2, p1 - p2);  // pbrt's triangle normal
    ASSERT_GT(glm::dot(n, p0 + p1 + p2), 0.f) << "triangle " << i / 3;
  }
  for (const Vec3& p : m.positions) ASSERT_NEAR(glm::length(p), 2.f, 1e-6f);
}

TEST(ProceduralMesh, UVSphereAreaConvergesToSphere) {
  // Inscribed polyhedra: area below 4 pi r^2, error falling as the mesh refines (about
  // quadratically in the spacing).
  double exact = 4 * kPiDouble * 9.0;  // r = 3
  double prev_err = 1e30;
  for (int k : {8, 16, 32, 64, 128}) {
    double err = exact - mesh_area(make_uv_sphere_mesh(k, 2 * k, 3.f));
    EXPECT_GT(err, 0.0);
    EXPECT_LT(err, prev_err / 3.0) << k;  // quadratic convergence gives about / 4
    prev_err = err;
  }
  EXPECT_LT(prev_err / exact, 2e-4);
}

TEST(ProceduralMesh, BuildsATriangleMeshWithoutDegenerates) {
  ProceduralMesh m = make_uv_sphere_mesh(50, 64);
  auto mesh = make_triangle_mesh(m, scale(Vec3(2, 2, 2)));
  EXPECT_EQ(mesh->dropped_triangles(), 0);
  EXPECT_EQ(mesh->primitive_count(), size_t(2 * 64 * 49));
  EXPECT_NEAR(mesh->area(), float(4 * mesh_area(m)), 1e-3f);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
