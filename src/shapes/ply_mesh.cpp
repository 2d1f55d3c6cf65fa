#include "shapes/ply_mesh.h"

#include <filesystem>

#include "core/error.h"
#include "scene/scene_files.h"
#include "shapes/ply_reader.h"

namespace eyetrace {

namespace {

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

MeshData read_ply_mesh(const std::string& path, const ParameterList& params) {
  if (ends_with(path, ".gz"))
    params.fail("filename", fmt::format("\"{}\": compressed PLY is not supported, gunzip it", path));
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    params.fail("filename", fmt::format("cannot open \"{}\": no such file", path));
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

std::vector<std::unique_ptr<Shape>> create_plymesh_shapes(const ShapeContext& ctx) {
  const ParameterList& params = ctx.params;
  std::string filename = params.get_string("filename", "");
  if (filename.empty()) params.fail("filename", "a PLY file name is required");
  std::filesystem::path path(resolve_scene_file(ctx.search_dir, filename));

  for (const char* name : {"displacement", "displacement.edgelength", "edgelength"}) {
    const Param* p = params.find(name);
    if (!p) continue;
    p->used = true;
    warn(p->loc, fmt::format("plymesh: parameter \"{}\": displacement is not supported; the mesh is used as is", name));
  }
  warn_alpha_unsupported(params, "plymesh");

  MeshData mesh = read_ply_mesh(path.string(), params);
  MeshSource source(params);
  source.p = source.indices = source.n = source.uv = "filename";
  source.context = fmt::format("\"{}\": ", path.string());
  std::vector<std::unique_ptr<Shape>> shapes;
  shapes.push_back(
      std::make_unique<TriangleMesh>(std::move(mesh), ctx.world_from_object, ctx.reverse_orientation, source));
  return shapes;
}

}  // namespace eyetrace
