// libFuzzer target: PLY meshes (parse_ply, the reader behind "plymesh"). A PlyError is the
// expected rejection; a mesh that is accepted holds what the header declared, and never more
// vertices than its bytes can encode (no allocation beyond the input's size).
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "shapes/ply_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  try {
    const eyetrace::MeshData mesh = eyetrace::parse_ply(bytes);
    const bool per_vertex_ok = (mesh.normals.empty() || mesh.normals.size() == mesh.positions.size()) &&
                               (mesh.uvs.empty() || mesh.uvs.size() == mesh.positions.size());
    if (!per_vertex_ok || mesh.indices.size() % 3 != 0 || mesh.positions.size() > size) {
      std::fprintf(stderr, "ply_fuzzer: invariant violated\n");
      std::abort();
    }
  } catch (const eyetrace::PlyError&) {
  }
  return 0;
}
