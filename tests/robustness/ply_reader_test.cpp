// The strict PLY reader (shapes/ply_reader.h): every layout pbrt scenes use reads back the
// numbers written by hand below, and malformed headers are PlyErrors that say what is wrong.
#include <cstring>
#include <string>

#include <gtest/gtest.h>

#include "../support/unity_id.h"
#include "shapes/ply_reader.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

std::string header(const std::string& format, const std::string& body) {
  return "ply\nformat " + format + " 1.0\n" + body + "end_header\n";
}

const char* kXYZ = "element vertex 4\nproperty float x\nproperty float y\nproperty float z\n";
const float kQuad[12] = {0, 0, 0, 2, 0, 0, 2, 1, 0, 0, 1, 0};

template <typename T>
std::string bytes_of(T v, bool big_endian) {
  std::string b(reinterpret_cast<const char*>(&v), sizeof v);
  if (big_endian) std::reverse(b.begin(), b.end());  // the test machine is little-endian
  return b;
}

std::string binary_quad(bool big_endian) {
  std::string data;
  for (float f : kQuad) data += bytes_of(f, big_endian);
  data += bytes_of(uint8_t(4), big_endian);
  for (int32_t i : {0, 1, 2, 3}) data += bytes_of(i, big_endian);
  return header(big_endian ? "binary_big_endian" : "binary_little_endian",
                std::string(kXYZ) + "element face 1\nproperty list uchar int vertex_indices\n") +
         data;
}

std::string ply_error(const std::string& bytes) {
  try {
    parse_ply(bytes);
  } catch (const PlyError& e) {
    return e.what();
  }
  return "";
}

TEST(PlyReader, ReadsEveryLayoutAsWritten) {
  for (bool big : {false, true}) {
    MeshData m = parse_ply(binary_quad(big));
    ASSERT_EQ(m.positions.size(), 4u);
    for (int i = 0; i < 4; ++i)
      EXPECT_EQ(m.positions[i], Vec3(kQuad[3 * i], kQuad[3 * i + 1], kQuad[3 * i + 2])) << big;
    EXPECT_EQ(m.indices, (std::vector<int>{0, 1, 2, 0, 2, 3}));
    EXPECT_TRUE(m.normals.empty());
    EXPECT_TRUE(m.uvs.empty());
  }
  // Normals, uv under pbrt's other names, properties and elements the reader does not use.
  std::string text = header("ascii",
                            "comment exported by hand\nelement vertex 3\nproperty float x\nproperty float y\n"
                            "property float z\nproperty float nx\nproperty float ny\nproperty float nz\n"
                            "property float s\nproperty float t\nproperty uchar red\n"
                            "element face 2\nproperty list uchar uint vertex_index\nproperty int face_indices\n"
                            "element material 1\nproperty list uchar float colour\n") +
                     "0 0 0 0 0 1 0.25 0.5 255\n1 0 0 0 0 1 1 0 0\n0 1 0 0 0 1 0 1e-400 7\n"
                     "3 0 1 2 11\n2 0 1 12\n3 0.5 0.5 0.5";  // a line (skipped); no final newline
  MeshData m = parse_ply(text);
  EXPECT_EQ(m.indices, (std::vector<int>{0, 1, 2}));
  ASSERT_EQ(m.normals.size(), 3u);
  EXPECT_EQ(m.normals[2], Vec3(0, 0, 1));
  ASSERT_EQ(m.uvs.size(), 3u);
  EXPECT_EQ(m.uvs[0], Vec2(0.25f, 0.5f));
  EXPECT_EQ(m.uvs[2], Vec2(0.f, 0.f));  // 1e-400 underflows to 0
  // An element without properties occupies no bytes, however many it declares (found by the
  // fuzzer: 17083783686 of them were once read one by one).
  m = parse_ply(header("ascii", std::string(kXYZ) + "element nothing 17083783686\n") + "0 0 0\n1 0 0\n0 1 0\n1 1 0\n");
  EXPECT_EQ(m.positions.size(), 4u);
}

TEST(PlyReader, MalformedFilesSayWhatIsWrong) {
  EXPECT_EQ(ply_error("this is not a ply file\n"), "not a PLY file (the first line is not \"ply\")");
  EXPECT_EQ(ply_error("ply\nformat ascii 1.0\nelement vertex 0\n"), "the header has no end_header line");
  EXPECT_EQ(ply_error(header("binary_middle_endian", "")), "header line 2: unsupported format");
  EXPECT_EQ(ply_error("ply\nproperty float x\nend_header\n"), "header line 2: a property before any element");
  EXPECT_EQ(ply_error(header("ascii", "element vertex -3\n")),
            "header line 3: element needs a name and a count (a whole number >= 0)");
  EXPECT_EQ(ply_error(header("ascii", "element vertex 1\nproperty float x\nproperty float y\n") + "0 0\n"),
            "the vertex element has no x, y and z properties");
  EXPECT_EQ(ply_error(header("ascii", std::string(kXYZ)) + "0 0 0\n1 0 0\n0 1 0\n0 0 zero\n"),
            "\"zero\" is not a number");
  EXPECT_EQ(ply_error(header("ascii", std::string(kXYZ) + "element face 1\nproperty list uchar int vertex_indices\n") +
                      "0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1.5 2\n"),
            "face 0: vertex index 1.5 is not an integer");
  std::string cut = binary_quad(false);
  EXPECT_EQ(ply_error(cut.substr(0, cut.size() - 1)), "the file ends in face 0 of the 1 its header declares");
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
