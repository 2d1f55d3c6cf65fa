#include "shapes/ply_mesh.h"

#include <filesystem>

#include "core/error.h"
#include "scene/scene_files.h"
#include "shapes/ply_reader.h"

namespace eyetrace {

MeshData read_ply_mesh(const std::string& path, const ParameterList& params) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    params.fail_missing_file("filename", fmt::format("cannot open \"{}\": no such file", path));
  MeshData mesh;
  try {
    mesh = read_ply_file(path);
  } catch (const PlyError& e) {
    params.fail("filename", fmt::format("cannot read \"{}\": {}", path, e.what()));
  }
  // Per-vertex data must cover every vertex or none.
  if (mesh.normals.size() != mesh.positions.size()) mesh.normals.clear();
  if (mesh.uvs.size() != mesh.positions.size()) mesh.uvs.clear();
  if (mesh.indices.empty()) params.fail("filename", fmt::format("\"{}\" contains no triangles or quads", path));
  return mesh;
}

const PluginSpec& plymesh_shape_spec() {
  static const PluginSpec spec{"Shape",
                               "a triangle mesh read from a PLY file",
                               "A gzip-compressed file (`.ply.gz`) is inflated first. No displacement.",
                               {param::string("filename")
                                    .shown_default("required")
                                    .describe("ascii or binary PLY, possibly gzip-compressed; vertex x y z, optional "
                                              "nx ny nz and u v (or s t); polygons are split into "
                                              "triangles"),
                                param::float_texture("displacement").describe("warns and is ignored"),
                                param::real("displacement.edgelength").describe("warns and is ignored"),
                                param::real("edgelength").describe("warns and is ignored"), alpha_param()}};
  return spec;
}

std::vector<std::unique_ptr<Shape>> create_plymesh_shapes(const ShapeContext& ctx) {
  const PluginParams params(ctx.params, plymesh_shape_spec(), "plymesh");
  if (!params.has("filename")) params.fail("filename", "a PLY file name is required");
  std::filesystem::path path(resolve_scene_file(ctx.search_dir, params.get_string("filename")));

  for (const char* name : {"displacement", "displacement.edgelength", "edgelength"})
    if (params.has(name)) params.warn_param(name, "displacement is not supported; the mesh is used as is");

  MeshData mesh = read_ply_mesh(path.string(), ctx.params);
  MeshSource source(ctx.params);
  source.p = source.indices = source.n = source.uv = "filename";
  source.context = fmt::format("\"{}\": ", path.string());
  std::vector<std::unique_ptr<Shape>> shapes;
  shapes.push_back(make_mesh_shape(std::move(mesh), ctx, params, source));
  return shapes;
}

}  // namespace eyetrace
