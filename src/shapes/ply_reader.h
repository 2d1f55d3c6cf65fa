// A strict reader for PLY meshes (pbrt-v4's "plymesh" files): ascii and binary (little or big
// endian), vertex positions with optional normals and uv, faces as vertex-index lists
// (polygons fan-triangulated; points and lines skipped). Every count in the header is checked
// against the bytes the file really holds before anything is read or allocated, so a file that
// lies about its size is an error that says so, never a crash or a runaway allocation (assimp,
// used before, crashed or took 13 GB on such files).
#pragma once
#include <stdexcept>
#include <string>

#include "shapes/triangle_mesh.h"

namespace eyetrace {

// What is wrong with a PLY file, without its path (the caller names the file).
class PlyError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Vertex indices are returned as written (3 per triangle); the mesh's own validation checks
// them against the vertex count. A gzip-compressed file (pbrt-v4's .ply.gz) is inflated first.
MeshData read_ply_file(const std::string& path);

// The same for a file's contents already in memory.
MeshData parse_ply(const std::string& bytes);

}  // namespace eyetrace
