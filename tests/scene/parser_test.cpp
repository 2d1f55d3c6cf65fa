// The pbrt-v4 parser on well-formed input: tokens, parameter values, graphics-state
// semantics and transforms, checked against hand-counted file positions and analytic
// matrices. Malformed input is covered in parser_errors_test.cpp.
#include "scene/parser.h"
#include "../support/unity_id.h"
#include "scene/param_spec.h"
#include "shapes/sphere.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "scene/tokenizer.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

namespace fs = std::filesystem;

const fs::path kDataDir = fs::path(EYETRACE_SOURCE_DIR) / "tests" / "data" / "parser";

SceneDescription parse(const std::string& text) { return parse_scene_string(text, "test.pbrt", kDataDir.string()); }

const Param& param_of(const ParameterList& list, const std::string& name) {
  const Param* p = list.find(name);
  if (!p) throw std::runtime_error("missing parameter " + name);
  return *p;
}

void expect_vec_near(const Vec3& got, const Vec3& want, float tol = 1e-5f) {
  EXPECT_NEAR(got.x, want.x, tol);
  EXPECT_NEAR(got.y, want.y, tol);
  EXPECT_NEAR(got.z, want.z, tol);
}

// ---------------------------------------------------------------------------------------
// Tokenizer

TEST(Tokenizer, KindsPositionsAndEscapes) {
  Tokenizer tok("Shape \"a\\\"b\\\\\" # comment [ ignored\n  [ -1.5e2 ]\"x\"", "t.pbrt");
  Token t = tok.next();
  EXPECT_EQ(t.kind, TokenKind::Word);
  EXPECT_EQ(t.text, "Shape");
  EXPECT_EQ(t.line, 1);
  EXPECT_EQ(t.column, 1);
  t = tok.next();
  EXPECT_EQ(t.kind, TokenKind::String);
  EXPECT_EQ(t.string_value(), "a\"b\\");
  EXPECT_EQ(t.column, 7);
  t = tok.next();
  EXPECT_EQ(t.kind, TokenKind::OpenBracket);
  EXPECT_EQ(t.line, 2);
  EXPECT_EQ(t.column, 3);
  t = tok.next();
  EXPECT_EQ(t.text, "-1.5e2");
  EXPECT_EQ(t.column, 5);
  EXPECT_EQ(tok.next().kind, TokenKind::CloseBracket);
  t = tok.next();  // a string right after ']' with no space
  EXPECT_EQ(t.kind, TokenKind::String);
  EXPECT_EQ(t.string_value(), "x");
  EXPECT_EQ(t.column, 13);
  EXPECT_EQ(tok.next().kind, TokenKind::End);
  EXPECT_EQ(tok.next().kind, TokenKind::End);  // stays at the end
}

// An exporter's comment with an unmatched quote (pbrt-v4-scenes' transparent-machines frames:
// `# Unknown material VrayAdvancedMaterial"`) ends at the line's end, like any comment.
TEST(Tokenizer, AQuoteInACommentOpensNoString) {
  Tokenizer tok("# Unknown material VrayAdvancedMaterial\"\nShape \"plymesh\" # \"\n\"x\"", "t.pbrt");
  EXPECT_EQ(tok.next().text, "Shape");
  EXPECT_EQ(tok.next().string_value(), "plymesh");
  const Token t = tok.next();
  EXPECT_EQ(t.string_value(), "x");
  EXPECT_EQ(t.line, 3);
  EXPECT_EQ(tok.next().kind, TokenKind::End);
}

TEST(Tokenizer, EscapeSequencesDecode) {
  Tokenizer tok(R"("tab\there\nnew\'q\'")", "t.pbrt");
  EXPECT_EQ(tok.next().string_value(), "tab\there\nnew'q'");
}

TEST(Tokenizer, NumbersParseLikeStrtod) {
  double v = 0;
  EXPECT_EQ(parse_number("+2e3", &v), NumberStatus::Ok);
  EXPECT_EQ(v, 2000.0);
  EXPECT_EQ(parse_number("-.5", &v), NumberStatus::Ok);
  EXPECT_EQ(v, -0.5);
  EXPECT_EQ(parse_number("5.", &v), NumberStatus::Ok);
  EXPECT_EQ(v, 5.0);
  EXPECT_EQ(parse_number("1e-400", &v), NumberStatus::Ok);  // underflow is zero, not an error
  EXPECT_EQ(v, 0.0);
  EXPECT_EQ(parse_number("1e400", &v), NumberStatus::OutOfRange);
  EXPECT_EQ(parse_number("-1e400", &v), NumberStatus::OutOfRange);
  EXPECT_EQ(parse_number("nan", &v), NumberStatus::NotFinite);
  EXPECT_EQ(parse_number("-inf", &v), NumberStatus::NotFinite);
  EXPECT_EQ(parse_number("0x10", &v), NumberStatus::NotANumber);
  EXPECT_EQ(parse_number("1.2.3", &v), NumberStatus::NotANumber);
  EXPECT_EQ(parse_number("+-1", &v), NumberStatus::NotANumber);
  EXPECT_EQ(parse_number("", &v), NumberStatus::NotANumber);
}

// ---------------------------------------------------------------------------------------
// Parameters

TEST(Parser, EveryParameterTypeStoresItsValues) {
  SceneDescription d = parse(R"(WorldBegin
Shape "test"
  "float f" 1.5 "integer i" [ -3 4 ] "bool b1" true "bool b2" "false" "bool b3" [ false true ]
  "string s" "hello" "point2 uv" [ 0 1 ] "vector2 v2" [ 2 3 ] "point3 p" [ 1 2 3 ]
  "vector3 v3" [ 4 5 6 ] "normal n" [ 0 0 1 ] "normal3 n3" [ 0 1 0 ] "point pp" [ 7 8 9 ]
  "vector vv" [ 1 0 0 ] "rgb c" [ .1 .2 .3 ] "color cc" [ 1 1 1 ] "spectrum s1" [ 300 .3 800 .8 ]
  "spectrum s2" "metal-Cu-eta" "spectrum s3" 2.5 "blackbody bb" 6500 "texture tex" "checks"
)");
  ASSERT_EQ(d.shapes.size(), 1u);
  const ParameterList& p = d.shapes[0].params;
  EXPECT_EQ(p.params().size(), 21u);
  EXPECT_EQ(param_of(p, "f").numbers, std::vector<double>{1.5});
  EXPECT_EQ(param_of(p, "i").numbers, (std::vector<double>{-3, 4}));
  EXPECT_EQ(param_of(p, "b1").bools, std::vector<bool>{true});
  EXPECT_EQ(param_of(p, "b2").bools, std::vector<bool>{false});
  EXPECT_EQ(param_of(p, "b3").bools, (std::vector<bool>{false, true}));
  EXPECT_EQ(param_of(p, "s").strings, std::vector<std::string>{"hello"});
  EXPECT_EQ(param_of(p, "uv").numbers.size(), 2u);
  EXPECT_EQ(param_of(p, "c").numbers, (std::vector<double>{.1, .2, .3}));
  EXPECT_EQ(param_of(p, "s1").numbers, (std::vector<double>{300, .3, 800, .8}));
  EXPECT_EQ(param_of(p, "s2").strings, std::vector<std::string>{"metal-Cu-eta"});
  EXPECT_EQ(param_of(p, "s3").numbers, std::vector<double>{2.5});
  EXPECT_EQ(param_of(p, "bb").numbers, std::vector<double>{6500});
  EXPECT_EQ(param_of(p, "tex").strings, std::vector<std::string>{"checks"});
  // pbrt-v3 spellings are kept as written; canonical_type() maps them.
  EXPECT_EQ(param_of(p, "pp").type, "point");
  EXPECT_EQ(param_of(p, "pp").canonical_type(), "point3");
  EXPECT_EQ(param_of(p, "cc").canonical_type(), "rgb");
  EXPECT_EQ(param_of(p, "n3").canonical_type(), "normal");
  // Typed getters agree with the stored values.
  EXPECT_EQ(p.get_ints("i"), (std::vector<int>{-3, 4}));
  EXPECT_EQ(p.get_point3("p", Vec3(0.f)), Vec3(1, 2, 3));
  EXPECT_EQ(p.get_vector3("vv", Vec3(0.f)), Vec3(1, 0, 0));
  EXPECT_EQ(p.get_texture("tex"), "checks");
}

TEST(Parser, ParameterLocationsPointAtTheDeclaration) {
  SceneDescription d = parse("WorldBegin\n\n   Shape \"sphere\"\n\t\"float radius\" 2\n");
  ASSERT_EQ(d.shapes.size(), 1u);
  EXPECT_EQ(d.shapes[0].loc.to_string(), "test.pbrt:3:4");
  EXPECT_EQ(d.shapes[0].params.loc().to_string(), "test.pbrt:3:4");
  EXPECT_EQ(param_of(d.shapes[0].params, "radius").loc.to_string(), "test.pbrt:4:2");
}

TEST(Parser, MillionsOfNumbersKeepEveryValue) {
  // 3 million values k + 0.25: exactly representable, so the sum is exact.
  const size_t n = 3'000'000;
  std::string text = "WorldBegin\nShape \"trianglemesh\" \"point3 P\" [";
  text.reserve(n * 12);
  for (size_t k = 0; k < n; ++k) {
    text += ' ';
    text += std::to_string(k);
    text += ".25";
  }
  text += " ]\n";
  SceneDescription d = parse(text);
  const std::vector<double>& v = param_of(d.shapes.at(0).params, "P").numbers;
  ASSERT_EQ(v.size(), n);
  double sum = 0;
  for (double x : v) sum += x;
  EXPECT_EQ(sum, double(n) * double(n - 1) / 2 + 0.25 * double(n));
  EXPECT_EQ(v[1234567], 1234567.25);
}

// ---------------------------------------------------------------------------------------
// A complete scene file

TEST(ParserFiles, BasicSceneRoundTrips) {
  SceneDescription d = parse_scene_file((kDataDir / "basic.pbrt").string());
  EXPECT_EQ(d.search_dir, fs::absolute(kDataDir).lexically_normal().string());

  EXPECT_TRUE(d.has_camera);
  EXPECT_EQ(d.camera.name, "perspective");
  EXPECT_EQ(d.camera.params.get_float("fov", 0.f), 45.f);
  EXPECT_EQ(d.camera.loc.line, 4);
  EXPECT_EQ(d.film.name, "rgb");
  EXPECT_EQ(d.film.params.get_int("xresolution", 0), 64);
  EXPECT_EQ(d.film.params.get_int("yresolution", 0), 32);
  EXPECT_EQ(d.film.params.get_string("filename", ""), "basic.exr");
  EXPECT_EQ(d.sampler.name, "independent");
  EXPECT_EQ(d.sampler.params.get_int("pixelsamples", 0), 16);
  EXPECT_EQ(d.integrator.name, "path");
  EXPECT_EQ(d.integrator.params.get_int("maxdepth", 0), 5);
  EXPECT_EQ(d.filter.name, "box");
  EXPECT_EQ(d.color_space, "srgb");

  ASSERT_EQ(d.lights.size(), 1u);
  EXPECT_EQ(d.lights[0].name, "distant");
  EXPECT_EQ(param_of(d.lights[0].params, "L").numbers, std::vector<double>{5500});
  EXPECT_EQ(d.lights[0].params.get_point3("from", Vec3(0.f)), Vec3(0, 10, 0));

  ASSERT_EQ(d.textures.size(), 1u);
  EXPECT_EQ(d.textures[0].texture_name, "checks");
  EXPECT_EQ(d.textures[0].value_type, "spectrum");
  EXPECT_EQ(d.textures[0].name, "checkerboard");
  EXPECT_EQ(d.textures[0].params.get_float("uscale", 0.f), 8.f);

  ASSERT_EQ(d.named_materials.size(), 1u);
  const SceneEntity& gold = d.named_materials.at("gold");
  EXPECT_EQ(gold.name, "conductor");
  EXPECT_TRUE(param_of(gold.params, "type").used);  // so the plugin check does not flag it
  EXPECT_EQ(param_of(gold.params, "eta").strings, std::vector<std::string>{"metal-Au-eta"});

  // The implicit default material plus one anonymous Material.
  ASSERT_EQ(d.materials.size(), 2u);
  EXPECT_EQ(d.materials[0].name, "diffuse");
  EXPECT_TRUE(d.materials[0].params.params().empty());
  EXPECT_EQ(d.materials[1].params.get_texture("reflectance"), "checks");

  ASSERT_EQ(d.area_lights.size(), 1u);
  EXPECT_EQ(d.area_lights[0].name, "diffuse");
  EXPECT_EQ(param_of(d.area_lights[0].params, "L").numbers, (std::vector<double>{4, 4, 4}));

  ASSERT_EQ(d.shapes.size(), 5u);
  const char* names[] = {"sphere", "trianglemesh", "disk", "sphere", "sphere"};
  const int material_index[] = {0, 1, -1, -1, 0};
  const char* material_name[] = {"", "", "gold", "gold", ""};
  const int area_light[] = {-1, -1, 0, 0, -1};
  for (int i = 0; i < 5; ++i) {
    SCOPED_TRACE(i);
    EXPECT_EQ(d.shapes[i].name, names[i]);
    EXPECT_EQ(d.shapes[i].material.index, material_index[i]);
    EXPECT_EQ(d.shapes[i].material.name, material_name[i]);
    EXPECT_EQ(d.shapes[i].area_light, area_light[i]);
  }
  EXPECT_EQ(d.shapes[0].loc.line, 18);
  EXPECT_EQ(param_of(d.shapes[0].params, "radius").loc.to_string(), (kDataDir / "basic.pbrt").string() + ":18:16");
  EXPECT_TRUE(d.shapes[0].world_from_object.is_identity());
  expect_vec_near(d.shapes[1].world_from_object.point(Vec3(0.f)), Vec3(1, 0, 0));
  EXPECT_EQ(d.shapes[1].params.get_ints("indices"), (std::vector<int>{0, 1, 2}));
  EXPECT_TRUE(d.shapes[4].world_from_object.is_identity());  // AttributeEnd restored it
}

TEST(ParserFiles, IncludeIsTextualAndRelativeToTheIncludingFile) {
  SceneDescription d = parse_scene_file((kDataDir / "include_main.pbrt").string());
  ASSERT_EQ(d.shapes.size(), 4u);
  // inc/child.pbrt set a material and a translation that stay in force after its Include...
  EXPECT_EQ(d.shapes[0].name, "disk");  // from inc/grandchild.pbrt, found next to inc/child.pbrt
  EXPECT_EQ(d.shapes[1].name, "sphere");
  for (int i = 0; i < 2; ++i) {
    EXPECT_EQ(d.shapes[i].material.index, 1);
    expect_vec_near(d.shapes[i].world_from_object.point(Vec3(0.f)), Vec3(0, 0, 3));
  }
  EXPECT_EQ(d.materials.at(1).name, "dielectric");
  // ...until the enclosing AttributeEnd in the including file.
  EXPECT_EQ(d.shapes[2].material.index, 0);
  EXPECT_TRUE(d.shapes[2].world_from_object.is_identity());
  EXPECT_EQ(d.shapes[3].name, "cylinder");  // Imported, in statement order (scene_import_test.cpp)
  EXPECT_EQ(d.shapes[0].loc.line, 2);
  EXPECT_EQ(fs::path(d.shapes[0].loc.file).filename(), "grandchild.pbrt");
  EXPECT_EQ(fs::path(d.shapes[0].loc.file).parent_path().filename(), "inc");
}

TEST(ParserFiles, IncludeFallsBackToTheSearchDirectory) {
  // inc/fallback.pbrt includes "inc/imported.pbrt", which is not in inc/inc/.
  SceneDescription d = parse_scene_file((kDataDir / "fallback_main.pbrt").string());
  ASSERT_EQ(d.shapes.size(), 1u);
  EXPECT_EQ(d.shapes[0].name, "cylinder");
  EXPECT_EQ(fs::path(d.shapes[0].loc.file).lexically_normal(), (kDataDir / "inc" / "imported.pbrt").lexically_normal());
}

// ---------------------------------------------------------------------------------------
// Graphics state

TEST(Parser, MaterialAndAreaLightAreScopedByAttributes) {
  SceneDescription d = parse(R"(WorldBegin
Material "conductor"
AttributeBegin
  Material "dielectric"
  AreaLightSource "diffuse" "rgb L" [ 1 1 1 ]
  ReverseOrientation
  Shape "sphere"
AttributeEnd
Shape "disk"
)");
  ASSERT_EQ(d.shapes.size(), 2u);
  EXPECT_EQ(d.materials.at(d.shapes[0].material.index).name, "dielectric");
  EXPECT_EQ(d.shapes[0].area_light, 0);
  EXPECT_TRUE(d.shapes[0].reverse_orientation);
  EXPECT_EQ(d.materials.at(d.shapes[1].material.index).name, "conductor");
  EXPECT_EQ(d.shapes[1].area_light, -1);
  EXPECT_FALSE(d.shapes[1].reverse_orientation);
}

TEST(Parser, AttributesAreDefaultsForLaterDirectives) {
  SceneDescription d = parse(R"(WorldBegin
AttributeBegin
  Attribute "shape" "float radius" 2 "integer unused_by_spheres" 3
  Attribute "light" "float scale" 4
  Attribute "material" "float roughness" 0.25
  Shape "sphere"
  Shape "sphere" "float radius" 5
  LightSource "point"
  Material "conductor"
AttributeEnd
Shape "sphere"
)");
  ASSERT_EQ(d.shapes.size(), 3u);
  EXPECT_EQ(d.shapes[0].params.get_float("radius", 1.f), 2.f);
  EXPECT_EQ(d.shapes[1].params.get_float("radius", 1.f), 5.f);  // the directive's own value wins
  EXPECT_FALSE(d.shapes[2].params.has("radius"));               // AttributeEnd dropped it
  // An attribute a plugin never reads is not an unused-parameter error (as in pbrt-v4).
  EXPECT_NO_THROW(PluginParams(d.shapes[0].params, sphere_shape_spec(), "sphere"));
  EXPECT_EQ(d.lights.at(0).params.get_float("scale", 1.f), 4.f);
  EXPECT_EQ(d.materials.back().params.get_float("roughness", 0.f), 0.25f);
}

TEST(Parser, OptionsBeforeWorldBeginAreRecorded) {
  SceneDescription d = parse(R"(Option "bool disablepixeljitter" true
Option "integer seed" 7
TransformTimes 0 1
ColorSpace "rec2020"
WorldBegin)");
  ASSERT_EQ(d.options.size(), 2u);
  EXPECT_EQ(d.options[0].name, "disablepixeljitter");
  EXPECT_EQ(d.options[0].params.get_bool("disablepixeljitter", false), true);
  EXPECT_EQ(d.options[1].params.get_int("seed", 0), 7);
  EXPECT_EQ(d.color_space, "rec2020");
  EXPECT_FALSE(d.has_camera);
  EXPECT_EQ(d.camera.name, "perspective");  // pbrt-v4's default
  EXPECT_EQ(d.materials.size(), 1u);
}

// Media are kept by name (resolved by the builder); only Attribute "medium" is ignored, warned.
TEST(Parser, MediaAreParsedAndAttributeMediumIsIgnoredWithAWarning) {
  int before = warning_count();
  SceneDescription d = parse(R"(MakeNamedMedium "fog_for_parser_test" "string type" "homogeneous"
WorldBegin
MediumInterface "fog_for_parser_test" ""
Attribute "medium" "float sigma_a" 1
Shape "sphere"
)");
  EXPECT_EQ(d.shapes.size(), 1u);
  EXPECT_EQ(warning_count() - before, 1);
  ASSERT_EQ(d.media.count("fog_for_parser_test"), 1u);
  EXPECT_EQ(d.media.at("fog_for_parser_test").name, "homogeneous");
  EXPECT_EQ(d.shapes[0].media.inside, "fog_for_parser_test");
  EXPECT_EQ(d.shapes[0].media.outside, "");
}

TEST(Parser, DirectiveTextFromTheCommandLine) {
  SceneEntity e = parse_directive_text(R"(Camera "thinlens" "float lensradius" 0.0025 "float focaldistance" 1.5)",
                                       "Camera", "--camera");
  EXPECT_EQ(e.name, "thinlens");
  EXPECT_EQ(e.params.get_float("lensradius", 0.f), 0.0025f);
  EXPECT_EQ(e.params.get_float("focaldistance", 0.f), 1.5f);
  EXPECT_EQ(e.loc.to_string(), "--camera:1:1");
  EXPECT_EQ(param_of(e.params, "lensradius").loc.to_string(), "--camera:1:19");
  // The keyword may be left out.
  SceneEntity f = parse_directive_text(R"("gaussian" "float sigma" 0.5)", "PixelFilter", "--filter");
  EXPECT_EQ(f.name, "gaussian");
  EXPECT_EQ(f.params.get_float("sigma", 0.f), 0.5f);
}

// ---------------------------------------------------------------------------------------
// Transforms (analytic answers)

TEST(ParserTransforms, TranslateThenRotateComposesAsPbrt) {
  // CTM = T(1,2,3) * R_z(90): a point is rotated first, then translated.
  SceneDescription d = parse("WorldBegin\nTranslate 1 2 3\nRotate 90 0 0 1\nShape \"sphere\"\n");
  const Transform& t = d.shapes.at(0).world_from_object;
  expect_vec_near(t.point(Vec3(1, 0, 0)), Vec3(1, 3, 3));  // (1,0,0) -> (0,1,0) -> (1,3,3)
  expect_vec_near(t.vector(Vec3(1, 0, 0)), Vec3(0, 1, 0));
  expect_vec_near(t.inverse().point(Vec3(1, 3, 3)), Vec3(1, 0, 0));
}

TEST(ParserTransforms, NegativeScaleFlipsHandedness) {
  SceneDescription d = parse("WorldBegin\nScale -1 1 1\nShape \"sphere\"\nIdentity\nShape \"disk\"\n");
  const Transform& t = d.shapes.at(0).world_from_object;
  EXPECT_TRUE(t.swaps_handedness());
  expect_vec_near(t.point(Vec3(1, 2, 3)), Vec3(-1, 2, 3));
  EXPECT_TRUE(d.shapes.at(1).world_from_object.is_identity());
  EXPECT_FALSE(d.shapes.at(1).world_from_object.swaps_handedness());
}

TEST(ParserTransforms, LookAtCameraLooksAtItsTarget) {
  SceneDescription d = parse("LookAt 0 0 5  0 0 0  0 1 0\nCamera \"perspective\"\nWorldBegin\n");
  const Transform& w = d.camera.world_from_camera;
  expect_vec_near(w.point(Vec3(0.f)), Vec3(0, 0, 5));
  expect_vec_near(w.vector(Vec3(0, 0, 1)), Vec3(0, 0, -1));  // +z looks at the target
  expect_vec_near(w.vector(Vec3(0, 1, 0)), Vec3(0, 1, 0));   // +y is up
  // pbrt's camera space is left-handed: +x = up x forward = (0,1,0) x (0,0,-1) = (-1,0,0).
  expect_vec_near(w.vector(Vec3(1, 0, 0)), Vec3(-1, 0, 0));
}

TEST(ParserTransforms, TransformMatrixUsesPbrtValueOrder) {
  // pbrt lists the translation in the last four values.
  SceneDescription d = parse(R"(WorldBegin
Transform [ 2 0 0 0  0 2 0 0  0 0 2 0  1 2 3 1 ]
Shape "sphere"
Translate 1 0 0
ConcatTransform [ 1 0 0 0  0 1 0 0  0 0 1 0  0 0 5 1 ]
Shape "disk"
Transform 1 0 0 0  0 1 0 0  0 0 1 0  7 0 0 1
Shape "cylinder"
)");
  expect_vec_near(d.shapes.at(0).world_from_object.point(Vec3(1, 1, 1)), Vec3(3, 4, 5));
  // (0,0,0) -> +5z -> +1x (local) -> *2 -> +(1,2,3)
  expect_vec_near(d.shapes.at(1).world_from_object.point(Vec3(0.f)), Vec3(3, 2, 13));
  expect_vec_near(d.shapes.at(2).world_from_object.point(Vec3(0.f)), Vec3(7, 0, 0));  // no brackets
}

TEST(ParserTransforms, WorldBeginResetsAndNamedSystemsRestore) {
  SceneDescription d = parse(R"(Translate 9 9 9
LookAt 1 2 3  1 2 4  0 1 0
Camera "perspective"
WorldBegin
Shape "sphere"
Translate 0 0 1
CoordinateSystem "lifted"
Translate 5 0 0
CoordSysTransform "camera"
Shape "disk"
CoordSysTransform "lifted"
Shape "cylinder"
CoordSysTransform "world"
Shape "cone"
)");
  ASSERT_EQ(d.shapes.size(), 4u);
  EXPECT_TRUE(d.shapes[0].world_from_object.is_identity());
  // The "camera" system is the camera's world_from_camera.
  EXPECT_TRUE(d.shapes[1].world_from_object == d.camera.world_from_camera);
  // Camera transform: LookAt applied after Translate 9 9 9 (CTM = T * LookAt).
  expect_vec_near(d.camera.world_from_camera.point(Vec3(0.f)), Vec3(1, 2, 3) - Vec3(9, 9, 9));
  expect_vec_near(d.shapes[2].world_from_object.point(Vec3(0.f)), Vec3(0, 0, 1));
  EXPECT_TRUE(d.shapes[3].world_from_object.is_identity());
}

TEST(ParserTransforms, TransformBeginRestoresTheTransformOnly) {
  // pbrt-v3 semantics: the material chosen inside survives TransformEnd.
  SceneDescription d = parse(R"(WorldBegin
TransformBegin
  Translate 1 0 0
  Material "conductor"
TransformEnd
Shape "sphere"
)");
  EXPECT_TRUE(d.shapes.at(0).world_from_object.is_identity());
  EXPECT_EQ(d.shapes.at(0).material.index, 1);
}

TEST(ParserTransforms, InstancesKeepDefinitionAndUseTransforms) {
  SceneDescription d = parse(R"(WorldBegin
ObjectBegin "tree"
  Translate 0 1 0
  Shape "sphere"
ObjectEnd
Translate 5 0 0
ObjectInstance "tree"
Shape "disk"
)");
  ASSERT_EQ(d.shapes.size(), 1u);  // the instanced sphere is not a top-level shape
  const InstanceDefinition& def = d.instances.at("tree");
  ASSERT_EQ(def.shapes.size(), 1u);
  expect_vec_near(def.shapes[0].world_from_object.point(Vec3(0.f)), Vec3(0, 1, 0));
  ASSERT_EQ(d.instance_uses.size(), 1u);
  const Transform& use = *d.instance_uses[0].world_from_instance;
  expect_vec_near(use.point(Vec3(0.f)), Vec3(5, 0, 0));  // ObjectEnd dropped the inner Translate
  expect_vec_near((use * def.shapes[0].world_from_object).point(Vec3(0.f)), Vec3(5, 1, 0));
  expect_vec_near(d.shapes[0].world_from_object.point(Vec3(0.f)), Vec3(5, 0, 0));
}

// ActiveTransform and TransformTimes: tests/scene/motion_blur_parse_test.cpp.

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
