#include "shapes/ply_mesh.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <assimp/Importer.hpp>
#include <filesystem>

#include "core/error.h"

namespace eyetrace {

namespace {

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

void append_mesh(const aiMesh& m, MeshData* out) {
  int base = int(out->positions.size());
  bool normals = m.HasNormals(), uvs = m.HasTextureCoords(0);
  for (unsigned i = 0; i < m.mNumVertices; ++i) {
    const aiVector3D& p = m.mVertices[i];
    out->positions.emplace_back(p.x, p.y, p.z);
    if (normals) out->normals.emplace_back(m.mNormals[i].x, m.mNormals[i].y, m.mNormals[i].z);
    if (uvs) out->uvs.emplace_back(m.mTextureCoords[0][i].x, m.mTextureCoords[0][i].y);
  }
  for (unsigned f = 0; f < m.mNumFaces; ++f) {
    const aiFace& face = m.mFaces[f];
    if (face.mNumIndices != 3) continue;  // points and lines left by the triangulation
    for (int k = 0; k < 3; ++k) out->indices.push_back(base + int(face.mIndices[k]));
  }
}

}  // namespace

MeshData read_ply_mesh(const std::string& path, const ParameterList& params) {
  if (ends_with(path, ".gz"))
    params.fail("filename", fmt::format("\"{}\": compressed PLY is not supported, gunzip it", path));
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    params.fail("filename", fmt::format("cannot open \"{}\": no such file", path));
  Assimp::Importer importer;
  // No vertex joining: the file's vertices and their order are kept as written.
  const aiScene* scene = importer.ReadFile(path, aiProcess_Triangulate);
  if (!scene || !scene->mRootNode)
    params.fail("filename", fmt::format("cannot read \"{}\": {}", path, importer.GetErrorString()));
  MeshData mesh;
  bool all_normals = true, all_uvs = true;
  for (unsigned i = 0; i < scene->mNumMeshes; ++i) {
    all_normals = all_normals && scene->mMeshes[i]->HasNormals();
    all_uvs = all_uvs && scene->mMeshes[i]->HasTextureCoords(0);
  }
  for (unsigned i = 0; i < scene->mNumMeshes; ++i) append_mesh(*scene->mMeshes[i], &mesh);
  // Per-vertex data must cover every vertex or none.
  if (!all_normals) mesh.normals.clear();
  if (!all_uvs) mesh.uvs.clear();
  if (mesh.indices.empty())
    params.fail("filename", fmt::format("\"{}\" contains no triangles or quads", path));
  return mesh;
}

std::vector<std::unique_ptr<Shape>> create_plymesh_shapes(const ShapeContext& ctx) {
  const ParameterList& params = ctx.params;
  std::string filename = params.get_string("filename", "");
  if (filename.empty()) params.fail("filename", "a PLY file name is required");
  std::filesystem::path path(filename);
  if (path.is_relative() && !ctx.search_dir.empty()) path = std::filesystem::path(ctx.search_dir) / path;

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
  shapes.push_back(std::make_unique<TriangleMesh>(std::move(mesh), ctx.world_from_object, ctx.reverse_orientation, source));
  return shapes;
}

}  // namespace eyetrace
