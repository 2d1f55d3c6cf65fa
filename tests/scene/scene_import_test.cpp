// Import as pbrt-v4 parses it: each imported file by a parser of its own, on a task of its own
// (ParseOptions::import_task_min_bytes 0 puts every Import on a task), merged in statement
// order. The reference is independent of that code: the same files Included, each wrapped in
// AttributeBegin/AttributeEnd (an imported file's graphics state ends with it), which the
// token-splicing Include path parses in order.
#include <gtest/gtest.h>

#include <fstream>
#include <limits>
#include <regex>

#include "../support/temp_files.h"
#include "../support/unity_id.h"
#include "scene/parser.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

namespace fs = std::filesystem;
using test::TempDir;

const ParseOptions kAllOnTasks{0};
const ParseOptions kNoTasks{std::numeric_limits<std::uintmax_t>::max()};

void write(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
}

// Writes the files into dir/imp as they are, and into dir/ref with every `Import "x"` made an
// `Include` of a file that wraps x in AttributeBegin/AttributeEnd.
void write_both(const TempDir& dir, const std::vector<std::pair<std::string, std::string>>& files) {
  const std::regex import_re("Import \"([^\"]+)\"");
  for (const auto& [name, text] : files) {
    write(dir.path() / "imp" / name, text);
    write(dir.path() / "ref" / name, std::regex_replace(text, import_re, "Include \"wrap_$1\""));
    for (std::sregex_iterator it(text.begin(), text.end(), import_re), end; it != end; ++it)
      write(dir.path() / "ref" / ("wrap_" + (*it)[1].str()),
            "AttributeBegin\nInclude \"" + (*it)[1].str() + "\"\nAttributeEnd\n");
  }
}

std::string where(const SourceLoc& loc) {
  return fmt::format("{}:{}:{}", fs::path(loc.file).filename().string(), loc.line, loc.column);
}

std::string matrix_text(const Transform& t) {
  std::string s;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) s += fmt::format("{:a} ", t.matrix()[c][r]);
  return s;
}

std::string entity_text(const SceneEntity& e) {
  std::string s = fmt::format("{} @{} [", e.name, where(e.loc));
  for (const Param& p : e.params.params())
    s += fmt::format("{} {} @{} n={} s={}; ", p.type, p.name, where(p.loc), p.numbers.size(), p.strings.size());
  return s + "]";
}

std::string shape_text(const ShapeEntity& s) {
  return fmt::format("{} mat={}/{} light={} rev={} medium={}|{} {}\n", entity_text(s), s.material.index,
                     s.material.name, s.area_light, s.reverse_orientation, s.media.inside, s.media.outside,
                     matrix_text(s.world_from_object));
}

// Everything the parser hands the builder, as text: equal texts, equal scenes.
std::string scene_text(const SceneDescription& d) {
  std::string s;
  for (const auto& e : d.materials) s += "material " + entity_text(e) + "\n";
  for (const auto& [name, e] : d.named_materials) s += "named " + name + " " + entity_text(e) + "\n";
  for (const auto& t : d.textures)
    s += fmt::format("texture {} {} {} {}\n", t.texture_name, t.value_type, entity_text(t),
                     matrix_text(t.world_from_object));
  for (const auto& e : d.area_lights) s += "area " + entity_text(e) + " " + matrix_text(e.world_from_object) + "\n";
  for (const auto& e : d.lights) s += "light " + entity_text(e) + " " + matrix_text(e.world_from_object) + "\n";
  for (const auto& [name, m] : d.media) s += "medium " + name + " " + entity_text(m) + "\n";
  for (const auto& sh : d.shapes) s += "shape " + shape_text(sh);
  for (const auto& [name, def] : d.instances) {
    s += fmt::format("object {} @{}\n", name, where(def.loc));
    for (const auto& sh : def.shapes) s += "  shape " + shape_text(sh);
  }
  for (const auto& u : d.instance_uses)
    s += fmt::format("use {} @{} {}\n", u.name, where(u.loc), matrix_text(*u.world_from_instance));
  return s + "colorspace " + d.color_space + "\n";
}

const std::vector<std::pair<std::string, std::string>> kScene = {
    {"main.pbrt",
     "LookAt 0 0 5 0 0 0 0 1 0\nCamera \"perspective\"\nWorldBegin\n"
     "Material \"conductor\"\n"
     "MakeNamedMaterial \"gold\" \"string type\" \"conductor\"\n"
     "Texture \"checks\" \"spectrum\" \"checkerboard\"\n"
     "AttributeBegin\n"
     "  Translate 1 0 0\n"
     "  AreaLightSource \"diffuse\" \"rgb L\" [1 1 1]\n"
     "  Import \"a.pbrt\"\n"
     "  Shape \"sphere\" \"float radius\" 0.5\n"
     "AttributeEnd\n"
     "Shape \"disk\"\n"
     "Import \"b.pbrt\"\n"
     "Shape \"sphere\" \"float radius\" 2\n"
     "Import \"sub/c.pbrt\"\n"
     "NamedMaterial \"from_c\"\n"
     "Shape \"cylinder\"\n"
     "ObjectInstance \"obj_b\"\n"
     "Material \"dielectric\"\n"
     "Shape \"sphere\" \"float radius\" 3\n"},
    {"a.pbrt",
     "Shape \"sphere\" \"float radius\" 0.25\n"
     "Material \"diffuse\" \"rgb reflectance\" [0.1 0.2 0.3]\n"
     "AttributeBegin\n"
     "  AreaLightSource \"diffuse\" \"rgb L\" [2 2 2]\n"
     "  Shape \"disk\" \"float radius\" 0.1\n"
     "AttributeEnd\n"
     "Include \"a_inc.pbrt\"\n"},
    {"a_inc.pbrt",
     "NamedMaterial \"gold\"\n"
     "Shape \"trianglemesh\" \"point3 P\" [0 0 0 1 0 0 0 1 0] \"integer indices\" [0 1 2]\n"
     "Texture \"a_tex\" \"float\" \"constant\" \"float value\" 0.5\n"},
    {"b.pbrt",
     "ObjectBegin \"obj_b\"\n"
     "  Material \"coateddiffuse\"\n"
     "  Shape \"sphere\" \"float radius\" 0.3\n"
     "ObjectEnd\n"
     "Translate 0 2 0\n"
     "ObjectInstance \"obj_b\"\n"
     "Import \"b_nested.pbrt\"\n"
     "Shape \"disk\" \"float radius\" 0.7\n"},
    {"b_nested.pbrt",
     "Material \"diffuse\"\n"
     "Shape \"sphere\" \"float radius\" 0.4\n"
     "MakeNamedMedium \"fog\" \"string type\" \"homogeneous\"\n"
     "LightSource \"point\" \"rgb I\" [1 1 1]\n"},
    {"sub/c.pbrt",
     "MakeNamedMaterial \"from_c\" \"string type\" \"diffuse\"\n"
     "Rotate 90 0 0 1\n"
     "Shape \"sphere\" \"float radius\" 0.6\n"},
};

TEST(SceneImport, ParsedOnTasksMakesTheSceneOfTheFilesIncludedInOrder) {
  TempDir dir("eyetrace-import");
  write_both(dir, kScene);
  const std::string reference = scene_text(parse_scene_file((dir.path() / "ref" / "main.pbrt").string()));
  const SceneDescription serial = parse_scene_file((dir.path() / "imp" / "main.pbrt").string(), kNoTasks);
  EXPECT_EQ(scene_text(serial), reference);
  // Tasks finish in any order: the merge must not depend on it.
  for (int run = 0; run < 20; ++run)
    ASSERT_EQ(scene_text(parse_scene_file((dir.path() / "imp" / "main.pbrt").string(), kAllOnTasks)), reference)
        << "run " << run;

  // And the reference is the scene the files describe, read off them by hand: shapes in
  // statement order, materials numbered in statement order (0 is the implicit diffuse).
  const std::vector<std::pair<std::string, std::string>> shapes = {
      {"sphere", "a.pbrt:1:1"},       {"disk", "a.pbrt:5:3"},       {"trianglemesh", "a_inc.pbrt:2:1"},
      {"sphere", "main.pbrt:11:3"},   {"disk", "main.pbrt:13:1"},   {"sphere", "b_nested.pbrt:2:1"},
      {"disk", "b.pbrt:8:1"},         {"sphere", "main.pbrt:15:1"}, {"sphere", "c.pbrt:3:1"},
      {"cylinder", "main.pbrt:18:1"}, {"sphere", "main.pbrt:21:1"}};
  ASSERT_EQ(serial.shapes.size(), shapes.size());
  for (size_t i = 0; i < shapes.size(); ++i) {
    EXPECT_EQ(serial.shapes[i].name, shapes[i].first) << i;
    EXPECT_EQ(where(serial.shapes[i].loc), shapes[i].second) << i;
  }
  const std::vector<std::string> materials = {"diffuse",       "conductor", "diffuse",
                                              "coateddiffuse", "diffuse",   "dielectric"};
  ASSERT_EQ(serial.materials.size(), materials.size());
  for (size_t i = 0; i < materials.size(); ++i) EXPECT_EQ(serial.materials[i].name, materials[i]) << i;
  EXPECT_EQ(serial.shapes[0].material.index, 1);  // the importing file's material at the Import
  EXPECT_EQ(serial.shapes[0].area_light, 0);      // and its area light
  EXPECT_EQ(serial.shapes[1].material.index, 2);
  EXPECT_EQ(serial.shapes[1].area_light, 1);
  EXPECT_EQ(serial.shapes[2].material.name, "gold");
  EXPECT_EQ(serial.shapes[3].material.index, 1);  // a.pbrt's Material ended with it
  EXPECT_EQ(serial.shapes[5].material.index, 4);
  EXPECT_EQ(serial.shapes[9].material.name, "from_c");  // defined in an Import, used after it
  EXPECT_EQ(serial.shapes[10].material.index, 5);
  EXPECT_EQ(serial.instances.at("obj_b").shapes.at(0).material.index, 3);
  ASSERT_EQ(serial.instance_uses.size(), 2u);
  EXPECT_EQ(where(serial.instance_uses[0].loc), "b.pbrt:6:1");
  EXPECT_EQ(serial.textures.size(), 2u);
  EXPECT_EQ(serial.media.count("fog"), 1u);
  EXPECT_EQ(serial.lights.size(), 1u);
  // Translate 1 0 0 at the Import of a.pbrt; Translate 0 2 0 in b.pbrt, not after it.
  EXPECT_EQ(serial.shapes[0].world_from_object.point(Vec3(0.f)), Vec3(1, 0, 0));
  EXPECT_EQ(serial.shapes[6].world_from_object.point(Vec3(0.f)), Vec3(0, 2, 0));
  EXPECT_EQ(serial.shapes[7].world_from_object.point(Vec3(0.f)), Vec3(0, 0, 0));
}

std::vector<std::string> listed(const ParsedScene& p) {
  std::vector<std::string> out;
  for (const Diagnostic& d : p.errors) out.push_back(where(d.loc) + " " + d.message);
  return out;
}

// Errors inside imported files keep their place (file:line:col) and come in statement order,
// among those of the importing file, whichever task finishes first.
TEST(SceneImport, ErrorsComeInStatementOrderWithTheirPlaces) {
  TempDir dir("eyetrace-import");
  write_both(dir, {{"main.pbrt",
                    "WorldBegin\nImport \"e1.pbrt\"\nRotate 10 0 0 0\nImport \"e2.pbrt\"\nImport \"absent.pbrt\"\n"
                    "Rotate 5 0 0 0\n"},
                   {"e1.pbrt", "Shape \"sphere\"\nScale 0 1 1\nAttributeBegin\n"},
                   {"e2.pbrt", "Shape \"disk\"\n  Rotate 1 0 0 0\n"}});
  const std::vector<std::string> expected = {
      "e1.pbrt:2:1 Scale: a zero factor makes the transform singular",
      "e1.pbrt:3:1 AttributeBegin has no matching AttributeEnd before the end of the imported file",
      "main.pbrt:3:1 Rotate: the rotation axis is the zero vector",
      "e2.pbrt:2:3 Rotate: the rotation axis is the zero vector",
      "main.pbrt:5:1 Import \"absent.pbrt\": file not found (looked for \"" +
          (dir.path() / "imp" / "absent.pbrt").string() + "\")",
      "main.pbrt:6:1 Rotate: the rotation axis is the zero vector"};
  const std::string main = (dir.path() / "imp" / "main.pbrt").string();
  EXPECT_EQ(listed(parse_scene_file_collecting(main, kNoTasks)), expected);
  for (int run = 0; run < 20; ++run) {
    ParsedScene p = parse_scene_file_collecting(main, kAllOnTasks);
    ASSERT_EQ(listed(p), expected) << "run " << run;
    EXPECT_EQ(p.errors.at(4).kind, DiagnosticKind::MissingFile);
    EXPECT_EQ(p.desc.shapes.size(), 2u);  // the directives that did not fail
  }
  // A render stops at them all, the first first.
  try {
    parse_scene_file(main, kAllOnTasks);
    FAIL() << "no error";
  } catch (const SceneError& e) {
    ASSERT_EQ(e.diagnostics().size(), expected.size());
    EXPECT_EQ(where(e.first().loc), "e1.pbrt:2:1");
  }
}

// Warnings too, delivered (here collected, as `eyetrace check` does) in statement order.
TEST(SceneImport, WarningsComeInStatementOrder) {
  TempDir dir("eyetrace-import");
  write_both(dir, {{"main.pbrt", "WorldBegin\nImport \"w1.pbrt\"\nWorldEnd\nImport \"w2.pbrt\"\nWorldEnd\n"},
                   {"w1.pbrt", "Shape \"sphere\"\n WorldEnd\n"},
                   {"w2.pbrt", "Attribute \"medium\" \"float x\" 1\n"}});
  const std::vector<std::string> expected = {"w1.pbrt:2:2", "main.pbrt:3:1", "w2.pbrt:1:1", "main.pbrt:5:1"};
  for (const ParseOptions& options : {kNoTasks, kAllOnTasks, kAllOnTasks, kAllOnTasks}) {
    WarningCollector collector;
    parse_scene_file((dir.path() / "imp" / "main.pbrt").string(), options);
    std::vector<std::string> got;
    for (const Diagnostic& d : collector.warnings()) got.push_back(where(d.loc));
    EXPECT_EQ(got, expected);
  }
}

std::string error_of(const fs::path& path) {
  try {
    parse_scene_file(path.string(), kAllOnTasks);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

// What pbrt-v4 refuses in an Import (parser.cpp, scene.cpp) is an error at the place.
TEST(SceneImport, WhatPbrtV4RefusesIsAnErrorAtItsPlace) {
  TempDir dir("eyetrace-import");
  const fs::path d = dir.path();
  write(d / "shape.pbrt", "Shape \"sphere\"\n");
  write(d / "before_world.pbrt", "Import \"shape.pbrt\"\nWorldBegin\n");
  EXPECT_NE(
      error_of(d / "before_world.pbrt").find("before_world.pbrt:1:1: error: Import is only allowed after WorldBegin"),
      std::string::npos);

  // An ObjectBegin of the importing file takes the imported shapes, but the imported file
  // cannot end it (pbrt-v4: "ObjectEnd called inside Import for instance definition").
  write(d / "end.pbrt", "Shape \"disk\"\nObjectEnd\n");
  write(d / "object.pbrt", "WorldBegin\nObjectBegin \"o\"\nImport \"end.pbrt\"\nObjectEnd\nObjectInstance \"o\"\n");
  EXPECT_NE(error_of(d / "object.pbrt")
                .find("end.pbrt:2:1: error: ObjectEnd in an imported file cannot end the ObjectBegin \"o\""),
            std::string::npos);
  write(d / "in_object.pbrt",
        "WorldBegin\nObjectBegin \"o\"\nImport \"shape.pbrt\"\nObjectEnd\nObjectInstance \"o\"\n");
  SceneDescription in_object = parse_scene_file((d / "in_object.pbrt").string(), kAllOnTasks);
  EXPECT_EQ(in_object.instances.at("o").shapes.size(), 1u);
  EXPECT_TRUE(in_object.shapes.empty());

  // Two imports defining one name: pbrt-v4's "multiply defined", at the second definition.
  write(d / "m1.pbrt", "MakeNamedMaterial \"m\" \"string type\" \"diffuse\"\n");
  write(d / "m2.pbrt", "Shape \"disk\"\nMakeNamedMaterial \"m\" \"string type\" \"conductor\"\n");
  write(d / "twice.pbrt", "WorldBegin\nImport \"m1.pbrt\"\nImport \"m2.pbrt\"\n");
  EXPECT_NE(error_of(d / "twice.pbrt")
                .find("m2.pbrt:2:1: error: MakeNamedMaterial: material \"m\" is already defined at " +
                      (d / "m1.pbrt").string() + ":1:1"),
            std::string::npos);

  write(d / "self.pbrt", "Shape \"disk\"\nImport \"self.pbrt\"\n");
  write(d / "loop.pbrt", "WorldBegin\nImport \"self.pbrt\"\n");
  EXPECT_NE(error_of(d / "loop.pbrt").find("self.pbrt:2:1: error: recursive Import of"), std::string::npos);
}

// An imported file's graphics state ends with it (pbrt-v4's CopyForImport), and a directive
// cannot run on past its end.
TEST(SceneImport, TheImportedFilesStateEndsWithIt) {
  TempDir dir("eyetrace-import");
  const fs::path d = dir.path();
  write(d / "state.pbrt", "Material \"conductor\"\nTranslate 0 0 4\nReverseOrientation\nShape \"disk\"\n");
  write(d / "main.pbrt", "WorldBegin\nImport \"state.pbrt\"\nShape \"sphere\"\n");
  for (const ParseOptions& options : {kNoTasks, kAllOnTasks}) {
    SceneDescription s = parse_scene_file((d / "main.pbrt").string(), options);
    ASSERT_EQ(s.shapes.size(), 2u);
    EXPECT_EQ(s.shapes[0].material.index, 1);
    EXPECT_TRUE(s.shapes[0].reverse_orientation);
    EXPECT_EQ(s.shapes[1].material.index, 0);
    EXPECT_FALSE(s.shapes[1].reverse_orientation);
    EXPECT_TRUE(s.shapes[1].world_from_object.is_identity());
  }
  // Coordinate systems named before the Import are known in it (pbrt-v4's imported parser
  // starts without them, warns and ignores the CoordSysTransform); one named in it ends with it.
  write(d / "coords.pbrt", "CoordSysTransform \"here\"\nShape \"disk\"\nCoordinateSystem \"inside\"\n");
  write(d / "coords_main.pbrt",
        "WorldBegin\nTranslate 0 5 0\nCoordinateSystem \"here\"\nIdentity\nImport \"coords.pbrt\"\n"
        "CoordSysTransform \"inside\"\n");
  for (const ParseOptions& options : {kNoTasks, kAllOnTasks}) {
    ParsedScene p = parse_scene_file_collecting((d / "coords_main.pbrt").string(), options);
    ASSERT_EQ(p.desc.shapes.size(), 1u);
    EXPECT_EQ(p.desc.shapes[0].world_from_object.point(Vec3(0.f)), Vec3(0, 5, 0));
    ASSERT_EQ(p.errors.size(), 1u);
    EXPECT_EQ(where(p.errors[0].loc), "coords_main.pbrt:6:1");
    EXPECT_EQ(p.errors[0].message, "CoordSysTransform: no coordinate system named \"inside\"");
  }
  write(d / "params.pbrt", "\"float radius\" 3\n");
  write(d / "split.pbrt", "WorldBegin\nShape \"sphere\"\nImport \"params.pbrt\"\n");
  EXPECT_NE(error_of(d / "split.pbrt").find("params.pbrt:1:1: error: unexpected string \"float radius\""),
            std::string::npos);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
