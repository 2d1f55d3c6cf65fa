#include "shapes/bilinear_mesh.h"

#include "core/error.h"

namespace eyetrace {

MeshData bilinear_patches_to_triangles(const std::vector<Vec3>& positions, const std::vector<int>& quad_indices,
                                       const std::vector<Vec3>& normals, const std::vector<Vec2>& uvs) {
  // Corners k of a patch in pbrt's order p00 p10 p01 p11. Triangles (p00, p10, p01) and
  // (p10, p11, p01): both have cross(p0 - p2, p1 - p2) along cross(dp/du, dp/dv) of the
  // patch, so the triangle normals face the way pbrt's patch normal faces.
  constexpr int kTriangles[6] = {0, 1, 2, 1, 3, 2};
  constexpr Vec2 kPatchUV[4] = {Vec2(0.f, 0.f), Vec2(1.f, 0.f), Vec2(0.f, 1.f), Vec2(1.f, 1.f)};
  MeshData mesh;
  size_t patches = quad_indices.size() / 4;
  mesh.indices.reserve(6 * patches);
  if (!uvs.empty()) {  // vertices can be shared
    mesh.positions = positions;
    mesh.normals = normals;
    mesh.uvs = uvs;
    for (size_t q = 0; q < patches; ++q)
      for (int k : kTriangles) mesh.indices.push_back(quad_indices[4 * q + k]);
    return mesh;
  }
  bool with_normals = !normals.empty();
  for (size_t q = 0; q < patches; ++q) {
    int base = int(mesh.positions.size());
    for (int k = 0; k < 4; ++k) {
      int v = quad_indices[4 * q + k];
      mesh.positions.push_back(positions.at(size_t(v)));
      if (with_normals) mesh.normals.push_back(normals.at(size_t(v)));
      mesh.uvs.push_back(kPatchUV[k]);
    }
    for (int k : kTriangles) mesh.indices.push_back(base + k);
  }
  return mesh;
}

const PluginSpec& bilinearmesh_shape_spec() {
  static const PluginSpec spec{
      "Shape",
      "bilinear patches, each made two triangles",
      "Each patch is two triangles: exact for planar patches, an approximation for twisted ones.",
      {param::point3s("P").shown_default("required").describe("vertex positions"),
       param::integers("indices").describe("4 per patch (optional for exactly 4 vertices)"),
       param::normals("N").describe("per-vertex shading normals"), param::point2s("uv").describe("per-vertex (u, v)"),
       param::integers("faceIndices").describe("one per patch (checked, otherwise unused)"),
       param::string("emissionfilename").describe("warns and is ignored"), alpha_param()}};
  return spec;
}

std::vector<std::unique_ptr<Shape>> create_bilinearmesh_shapes(const ShapeContext& ctx) {
  const PluginParams params(ctx.params, bilinearmesh_shape_spec(), "bilinearmesh");
  std::vector<Vec3> positions = params.get_point3s("P");
  std::vector<int> indices = params.get_ints("indices");
  std::vector<Vec3> normals = params.get_normals("N");
  std::vector<Vec2> uvs = params.get_point2s("uv");
  std::vector<int> face_indices = params.get_ints("faceIndices");
  if (params.has("emissionfilename"))
    params.warn_param("emissionfilename", "image-driven emission sampling is not supported; ignored");

  size_t nv = positions.size();
  if (nv == 0) params.fail("P", "the mesh has no vertex positions");
  if (indices.empty()) {
    if (nv != 4)
      params.fail("indices", fmt::format("vertex indices are required unless the mesh has exactly 4 vertices "
                                         "(it has {})",
                                         nv));
    indices = {0, 1, 2, 3};
  }
  if (indices.size() % 4 != 0)
    params.fail("indices", fmt::format("{} vertex indices is not a multiple of 4", indices.size()));
  for (size_t i = 0; i < indices.size(); ++i)
    if (indices[i] < 0 || size_t(indices[i]) >= nv)
      params.fail("indices",
                  fmt::format("index {} (entry {}) is out of range: there are {} vertices", indices[i], i, nv));
  if (!normals.empty() && normals.size() != nv)
    params.fail("N", fmt::format("{} normals given for {} vertices", normals.size(), nv));
  if (!uvs.empty() && uvs.size() != nv)
    params.fail("uv", fmt::format("{} uv values given for {} vertices", uvs.size(), nv));
  if (!face_indices.empty() && face_indices.size() != indices.size() / 4)
    params.fail("faceIndices",
                fmt::format("{} face indices given for {} patches", face_indices.size(), indices.size() / 4));

  MeshData mesh = bilinear_patches_to_triangles(positions, indices, normals, uvs);
  std::vector<std::unique_ptr<Shape>> shapes;
  shapes.push_back(make_mesh_shape(std::move(mesh), ctx, params, MeshSource{ctx.params}));
  return shapes;
}

}  // namespace eyetrace
