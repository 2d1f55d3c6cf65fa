// The resume fingerprint covers the content of every file a scene reads, not only the scene
// text: a texture changed after a checkpoint must make --resume refuse the old state, and an
// unchanged one must not.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "../support/unity_id.h"
#include "render/render_state.h"
#include "scene/parser.h"
#include "scene/scene_builder.h"
#include "scene/scene_fingerprint.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

namespace fs = std::filesystem;

// A 2x2 PGM image (OIIO reads it): one grey level everywhere.
void write_image(const fs::path& path, int grey) {
  std::ofstream f(path, std::ios::binary);
  f << "P2\n2 2\n255\n" << grey << " " << grey << "\n" << grey << " " << grey << "\n";
}

const char* kScene = R"(
Film "rgb" "integer xresolution" 4 "integer yresolution" 4
Camera "perspective"
WorldBegin
Texture "wall" "spectrum" "imagemap" "string filename" "wall.pgm"
Material "diffuse" "texture reflectance" "wall"
Shape "sphere"
)";

uint64_t fingerprint_of(const fs::path& dir) {
  SceneDescription d = parse_scene_string(kScene, (dir / "scene.pbrt").string(), dir.string());
  RenderSetup setup = build_render_setup(d, RenderOverrides{});
  EXPECT_EQ(setup.files_read.size(), 1u);
  return scene_fingerprint(d, "options", setup.files_read);
}

TEST(SceneFingerprint, CoversTheContentOfFilesTheSceneReads) {
  const fs::path dir = fs::temp_directory_path() / "eyetrace_fingerprint_test";
  fs::create_directories(dir);
  write_image(dir / "wall.pgm", 100);
  const uint64_t first = fingerprint_of(dir);
  EXPECT_EQ(fingerprint_of(dir), first) << "the same files must give the same fingerprint";
  write_image(dir / "wall.pgm", 101);
  EXPECT_NE(fingerprint_of(dir), first) << "a changed texture must change the fingerprint";
  fs::remove_all(dir);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
