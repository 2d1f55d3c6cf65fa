// Include and Import as pbrt-v4 reads them: spliced at the token level (a directive or a
// parameter list goes on across a file boundary, as pbrt-v4-scenes' smoke-plume writes it),
// and gzip-compressed files inflated, with a clear error naming the file when the stream is
// truncated or corrupt. Compressed files are written by zlib's own gzip writer.
#include <gtest/gtest.h>

#include <fstream>

#include "../support/gzip_file.h"
#include "../support/temp_files.h"
#include "../support/unity_id.h"
#include "scene/parser.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

using test::TempDir;

void write(const TempDir& dir, const std::string& name, const std::string& text) {
  std::ofstream(dir.file(name), std::ios::binary) << text;
}

void write_gz(const TempDir& dir, const std::string& name, const std::string& text) {
  test::write_gzip_file(dir.file(name), text);
}

std::string error_of(const std::string& path) {
  try {
    parse_scene_file(path);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

// smoke-plume/plume.pbrt: the included file ends inside MakeNamedMedium's parameter list, and
// the including file goes on with more of its parameters.
TEST(ParserInclude, ParameterListContinuesAfterTheInclude) {
  TempDir dir("eyetrace-include");
  write(dir, "head.pbrt", "Shape \"sphere\" \"float zmin\" -0.5\n");
  write(dir, "main.pbrt", "WorldBegin\nInclude \"head.pbrt\"\n  \"float radius\" 2\nShape \"disk\"\n");
  SceneDescription d = parse_scene_file(dir.file("main.pbrt"));
  ASSERT_EQ(d.shapes.size(), 2u);
  EXPECT_EQ(d.shapes[0].name, "sphere");
  EXPECT_EQ(d.shapes[0].params.get_float("radius", 0.f), 2.f);
  EXPECT_EQ(d.shapes[0].params.get_float("zmin", 0.f), -0.5f);
  EXPECT_EQ(d.shapes[0].params.find("zmin")->loc.to_string(), dir.file("head.pbrt") + ":1:16");
  EXPECT_EQ(d.shapes[0].params.find("radius")->loc.to_string(), dir.file("main.pbrt") + ":3:3");
  EXPECT_EQ(d.shapes[1].name, "disk");
}

// The other way round: a directive of the including file takes its parameters from the file.
TEST(ParserInclude, DirectiveTakesItsParametersFromTheIncludedFile) {
  TempDir dir("eyetrace-include");
  write(dir, "params.pbrt", "\"float radius\" 3\n");
  write(dir, "main.pbrt", "WorldBegin\nShape \"sphere\"\nInclude \"params.pbrt\"\nShape \"disk\"\n");
  // "Include" is a bare word where a parameter could follow: it ends the parameter list, and
  // the included parameters then stand where a directive was expected.
  const std::string e = error_of(dir.file("main.pbrt"));
  EXPECT_NE(e.find(dir.file("params.pbrt") + ":1:1: error: unexpected string \"float radius\""), std::string::npos)
      << e;
}

TEST(ParserInclude, GzipCompressedIncludeAndImport) {
  TempDir dir("eyetrace-include");
  write_gz(dir, "geometry.pbrt.gz", "Shape \"sphere\" \"float radius\" 4\n");
  write_gz(dir, "more.pbrt.gz", "Shape \"disk\"\n");
  write(dir, "main.pbrt", "WorldBegin\nInclude \"geometry.pbrt.gz\"\nImport \"more.pbrt.gz\"\n");
  SceneDescription d = parse_scene_file(dir.file("main.pbrt"));
  ASSERT_EQ(d.shapes.size(), 2u);
  EXPECT_EQ(d.shapes[0].params.get_float("radius", 0.f), 4.f);
  EXPECT_EQ(d.shapes[0].loc.to_string(), dir.file("geometry.pbrt.gz") + ":1:1");
  EXPECT_EQ(d.shapes[1].name, "disk");
}

// Messages inside a compressed file point at its decompressed text.
TEST(ParserInclude, ErrorsInACompressedFileNameItsLines) {
  TempDir dir("eyetrace-include");
  write_gz(dir, "bad.pbrt.gz", "# comment\nShape \"sphere\" \"float radius\" [ 1\n");
  write(dir, "main.pbrt", "WorldBegin\nInclude \"bad.pbrt.gz\"\nShape \"disk\"\n");
  // The list is spliced on into main.pbrt (as in pbrt-v4), where "Shape" ends it.
  const std::string e = error_of(dir.file("main.pbrt"));
  EXPECT_NE(e.find(dir.file("main.pbrt") +
                   ":3:1: error: parameter \"float radius\": expected a number, got \"Shape\" "
                   "(is the ']' for the '[' at " +
                   dir.file("bad.pbrt.gz") + ":2:31 missing?)"),
            std::string::npos)
      << e;
}

TEST(ParserInclude, TruncatedGzipIsAnErrorNamingTheFile) {
  TempDir dir("eyetrace-include");
  write_gz(dir, "whole.pbrt.gz", "Shape \"sphere\" \"float radius\" 4\n");
  const std::string gz = test::read_text(dir.file("whole.pbrt.gz"));
  write(dir, "cut.pbrt.gz", gz.substr(0, gz.size() - 6));
  write(dir, "main.pbrt", "WorldBegin\nInclude \"cut.pbrt.gz\"\n");
  const std::string e = error_of(dir.file("main.pbrt"));
  EXPECT_NE(e.find(dir.file("main.pbrt") + ":2:1: error: cannot read scene file \"" + dir.file("cut.pbrt.gz") +
                   "\": gzip-compressed file: the gzip stream ends early (the file is truncated)"),
            std::string::npos)
      << e;
}

TEST(ParserInclude, CorruptGzipIsAnErrorNamingTheFile) {
  TempDir dir("eyetrace-include");
  write_gz(dir, "whole.pbrt.gz", "Shape \"sphere\" \"float radius\" 4\n");
  std::string gz = test::read_text(dir.file("whole.pbrt.gz"));
  gz[gz.size() - 7] = char(gz[gz.size() - 7] ^ 0xff);  // CRC-32
  write(dir, "bad.pbrt.gz", gz);
  write(dir, "main.pbrt", "WorldBegin\nInclude \"bad.pbrt.gz\"\n");
  const std::string e = error_of(dir.file("main.pbrt"));
  EXPECT_NE(e.find(dir.file("main.pbrt") + ":2:1: error: cannot read scene file \"" + dir.file("bad.pbrt.gz") +
                   "\": gzip-compressed file: corrupt gzip data"),
            std::string::npos)
      << e;
}

// The top-level file may be compressed too.
TEST(ParserInclude, CompressedTopLevelFile) {
  TempDir dir("eyetrace-include");
  write_gz(dir, "scene.pbrt.gz", "WorldBegin\nShape \"sphere\"\n");
  EXPECT_EQ(parse_scene_file(dir.file("scene.pbrt.gz")).shapes.size(), 1u);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
