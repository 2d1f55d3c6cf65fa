// PLY meshes through the strict reader: a small ASCII PLY written by the test is read back and traced;
// quads are triangulated; gzip-compressed files are inflated; unreadable, missing and
// truncated files are errors naming
// "filename" and the path.
#include "shapes/ply_mesh.h"
#include "../support/unity_id.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>

#include "../support/gzip_file.h"
#include "../support/temp_files.h"
#include "render/scene.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

namespace fs = std::filesystem;

fs::path temp_dir() {
  fs::path dir = fs::temp_directory_path() / ("eyetrace_ply_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir;
}

void write_file(const fs::path& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
}

// The unit square in z = 0 as two triangles, with normals +z and uv = (x, y).
const char* kSquarePly =
    "ply\n"
    "format ascii 1.0\n"
    "element vertex 4\n"
    "property float x\nproperty float y\nproperty float z\n"
    "property float nx\nproperty float ny\nproperty float nz\n"
    "property float u\nproperty float v\n"
    "element face 2\n"
    "property list uchar int vertex_indices\n"
    "end_header\n"
    "0 0 0 0 0 1 0 0\n"
    "1 0 0 0 0 1 1 0\n"
    "1 1 0 0 0 1 1 1\n"
    "0 1 0 0 0 1 0 1\n"
    "3 0 1 2\n"
    "3 0 2 3\n";

// A 2 x 1 rectangle in the plane z = 3 written as one quad, no normals or uvs.
const char* kQuadPly =
    "ply\n"
    "format ascii 1.0\n"
    "element vertex 4\n"
    "property float x\nproperty float y\nproperty float z\n"
    "element face 1\n"
    "property list uchar int vertex_indices\n"
    "end_header\n"
    "0 0 3\n2 0 3\n2 1 3\n0 1 3\n"
    "4 0 1 2 3\n";

ParameterList ply_params(const std::string& filename, bool with_displacement = false) {
  ParameterList pl(SourceLoc{"ply.pbrt", 4, 1});
  Param p;
  p.type = "string";
  p.name = "filename";
  p.loc = SourceLoc{"ply.pbrt", 4, 8};
  p.strings = {filename};
  pl.add(p);
  if (with_displacement) {
    Param d;
    d.type = "texture";
    d.name = "displacement";
    d.loc = SourceLoc{"ply.pbrt", 4, 30};
    d.strings = {"bumps"};
    pl.add(d);
    Param e;
    e.type = "float";
    e.name = "edgelength";
    e.loc = SourceLoc{"ply.pbrt", 4, 50};
    e.numbers = {0.1};
    pl.add(e);
  }
  return pl;
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(PlyMesh, AsciiRoundTripTracesAsWritten) {
  fs::path dir = temp_dir();
  write_file(dir / "square.ply", kSquarePly);
  ParameterList pl = ply_params("square.ply");
  auto shapes = create_plymesh_shapes(ShapeContext{pl, translate(Vec3(0, 0, 1)), false, dir.string()});
  ASSERT_EQ(shapes.size(), 1u);
  EXPECT_EQ(shapes[0]->primitive_count(), 2u);
  EXPECT_NEAR(shapes[0]->area(), 1.f, 1e-6f);
  Scene scene;
  scene.add_primitive(Primitive{std::move(shapes[0]), nullptr, nullptr});
  scene.commit();
  for (Vec2 xy : {Vec2(0.7f, 0.2f), Vec2(0.25f, 0.5f)}) {  // one point in each triangle
    SurfaceInteraction si;
    ASSERT_TRUE(scene.intersect(Ray{Vec3(xy, 3.f), Vec3(0, 0, -1)}, &si));
    EXPECT_NEAR(si.t, 2.f, 1e-6f);
    EXPECT_NEAR(si.uv.x, xy.x, 1e-6f);  // the file's uv = (x, y)
    EXPECT_NEAR(si.uv.y, xy.y, 1e-6f);
    EXPECT_NEAR(si.ns.z, 1.f, 1e-6f);
    EXPECT_NEAR(si.n.z, 1.f, 1e-6f);
  }
  fs::remove_all(dir);
}

// pbrt-v4 scenes ship meshes as .ply.gz: written by zlib, read back as the same mesh.
TEST(PlyMesh, GzipCompressedFileIsTheSameMesh) {
  fs::path dir = temp_dir();
  test::write_gzip_file((dir / "square.ply.gz").string(), kSquarePly);
  ParameterList pl = ply_params("square.ply.gz");
  auto shapes = create_plymesh_shapes(ShapeContext{pl, Transform(), false, dir.string()});
  ASSERT_EQ(shapes.size(), 1u);
  EXPECT_EQ(shapes[0]->primitive_count(), 2u);
  EXPECT_NEAR(shapes[0]->area(), 1.f, 1e-6f);
  EXPECT_EQ(shapes[0]->bounds().hi, Vec3(1, 1, 0));
  // A truncated stream is an error naming the file, not a partial mesh.
  std::string gz = test::read_text(dir / "square.ply.gz");
  write_file(dir / "cut.ply.gz", gz.substr(0, gz.size() / 2));
  std::string e = error_of([&] {
    ParameterList cut = ply_params("cut.ply.gz");
    create_plymesh_shapes(ShapeContext{cut, Transform(), false, dir.string()});
  });
  EXPECT_NE(e.find("cut.ply.gz"), std::string::npos) << e;
  EXPECT_NE(e.find("gzip-compressed file"), std::string::npos) << e;
  fs::remove_all(dir);
}

TEST(PlyMesh, QuadsAreTriangulated) {
  fs::path dir = temp_dir();
  write_file(dir / "quad.ply", kQuadPly);
  ParameterList pl = ply_params((dir / "quad.ply").string());  // absolute path
  auto shapes = create_plymesh_shapes(ShapeContext{pl, Transform(), false, "/nonexistent"});
  EXPECT_EQ(shapes.at(0)->primitive_count(), 2u);
  EXPECT_NEAR(shapes[0]->area(), 2.f, 1e-6f);
  Bounds3 b = shapes[0]->bounds();
  EXPECT_EQ(b.lo, Vec3(0, 0, 3));
  EXPECT_EQ(b.hi, Vec3(2, 1, 3));
  fs::remove_all(dir);
}

TEST(PlyMesh, DisplacementWarnedAndMarkedUsed) {
  fs::path dir = temp_dir();
  write_file(dir / "quad.ply", kQuadPly);
  ParameterList pl = ply_params("quad.ply", true);
  create_plymesh_shapes(ShapeContext{pl, Transform(), false, dir.string()});
  for (const Param& p : pl.params()) EXPECT_TRUE(p.used) << p.name;
  fs::remove_all(dir);
}

TEST(PlyMesh, FileErrorsNameParameterAndPath) {
  fs::path dir = temp_dir();
  std::string e = error_of([&] {
    ParameterList pl = ply_params("missing.ply");
    create_plymesh_shapes(ShapeContext{pl, Transform(), false, dir.string()});
  });
  EXPECT_NE(e.find("\"filename\""), std::string::npos) << e;
  EXPECT_NE(e.find((dir / "missing.ply").string()), std::string::npos) << e;
  EXPECT_NE(e.find("ply.pbrt:4:8"), std::string::npos) << e;

  write_file(dir / "junk.ply", "this is not a ply file\n");
  e = error_of([&] {
    ParameterList pl = ply_params("junk.ply");
    create_plymesh_shapes(ShapeContext{pl, Transform(), false, dir.string()});
  });
  EXPECT_NE(e.find("\"filename\""), std::string::npos) << e;
  EXPECT_NE(e.find("cannot read"), std::string::npos) << e;

  write_file(dir / "mesh.ply.gz", "\x1f\x8b");  // gzip's magic bytes, then nothing
  e = error_of([&] {
    ParameterList pl = ply_params("mesh.ply.gz");
    create_plymesh_shapes(ShapeContext{pl, Transform(), false, dir.string()});
  });
  EXPECT_NE(e.find("\"filename\""), std::string::npos) << e;
  EXPECT_NE(e.find("mesh.ply.gz"), std::string::npos) << e;
  EXPECT_NE(e.find("gzip-compressed file"), std::string::npos) << e;

  // Vertices but no faces: an empty mesh.
  write_file(dir / "points.ply",
             "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
             "end_header\n0 0 0\n1 0 0\n0 1 0\n");
  e = error_of([&] {
    ParameterList pl = ply_params("points.ply");
    create_plymesh_shapes(ShapeContext{pl, Transform(), false, dir.string()});
  });
  EXPECT_NE(e.find("\"filename\""), std::string::npos) << e;
  EXPECT_NE(e.find("points.ply"), std::string::npos) << e;

  e = error_of([&] {
    ParameterList pl(SourceLoc{"ply.pbrt", 4, 1});
    create_plymesh_shapes(ShapeContext{pl, Transform(), false, dir.string()});
  });
  EXPECT_NE(e.find("\"filename\""), std::string::npos) << e;
  fs::remove_all(dir);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
