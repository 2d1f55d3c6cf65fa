#include "shapes/procedural_mesh.h"

#include <stdexcept>

namespace eyetrace {

ProceduralMesh make_uv_sphere_mesh(int rings, int segments, float radius) {
  if (rings < 2 || segments < 3) throw std::invalid_argument("make_uv_sphere_mesh: needs rings >= 2 and segments >= 3");
  ProceduralMesh m;
  auto vertex = [&](double theta, double phi) {
    glm::dvec3 n(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
    m.positions.push_back(Vec3(n * double(radius)));
    m.normals.push_back(Vec3(n));
  };
  const double pi = kPiDouble;
  vertex(0.0, 0.0);  // north pole: index 0
  for (int r = 1; r < rings; ++r)
    for (int s = 0; s < segments; ++s) vertex(pi * r / rings, 2.0 * pi * s / segments);
  vertex(pi, 0.0);  // south pole: last index
  int south = int(m.positions.size()) - 1;
  auto ring_vertex = [&](int r, int s) { return 1 + (r - 1) * segments + (s % segments); };
  auto tri = [&](int a, int b, int c) { m.indices.insert(m.indices.end(), {a, b, c}); };
  // Orientation: with phi increasing counter-clockwise about +z and theta from the north
  // pole, (north, ring(s), ring(s+1)) winds counter-clockwise seen from outside.
  for (int s = 0; s < segments; ++s) tri(0, ring_vertex(1, s), ring_vertex(1, s + 1));
  for (int r = 1; r < rings - 1; ++r)
    for (int s = 0; s < segments; ++s) {
      int a = ring_vertex(r, s), b = ring_vertex(r, s + 1);
      int c = ring_vertex(r + 1, s), d = ring_vertex(r + 1, s + 1);
      tri(a, c, d);
      tri(a, d, b);
    }
  for (int s = 0; s < segments; ++s) tri(south, ring_vertex(rings - 1, s + 1), ring_vertex(rings - 1, s));
  return m;
}

std::unique_ptr<TriangleMesh> make_triangle_mesh(const ProceduralMesh& mesh, const Transform& world_from_object) {
  ParameterList no_params;  // procedural data has no scene parameters to blame
  return std::make_unique<TriangleMesh>(MeshData{mesh.positions, mesh.indices, mesh.normals, {}}, world_from_object,
                                        false, MeshSource(no_params));
}

}  // namespace eyetrace
