// One handler per pbrt-v4 directive, and the graphics state they share (current transform,
// material, area light, attributes, the AttributeBegin/End stack). Semantics follow
// pbrt-v4's BasicSceneBuilder; where eyetrace departs from it it warns by name instead of
// guessing.
#include "scene/scene_parser.h"

#include <algorithm>
#include <stdexcept>

#include <glm/gtc/type_ptr.hpp>

#include "core/animated_transform.h"
#include "scene/param_reader.h"

namespace eyetrace::parsing {

namespace {

bool is_finite(const Mat4& m) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(m[c][r])) return false;
  return true;
}

// Largest |entry| of columns [c0, c1) in the affine rows of m.
float max_entry(const Mat4& m, int c0, int c1) {
  float v = 0.f;
  for (int c = c0; c < c1; ++c)
    for (int r = 0; r < 3; ++r) v = std::max(v, std::abs(m[c][r]));
  return v;
}

// The renderer squares lengths in float (3.4e38): a transform that stretches (or, through
// its inverse, shrinks) lengths beyond 1e18 makes distances and normals overflow later, far
// from the directive that caused it. Returns why, or "" when the transform is usable.
std::string overflow_reason(const Transform& t) {
  constexpr float kLimit = 1e18f;
  float stretch = max_entry(t.matrix(), 0, 3), shrink = max_entry(t.inverse_matrix(), 0, 3);
  float shift = max_entry(t.matrix(), 3, 4);
  if (stretch > kLimit) return fmt::format("overflow: it scales lengths by up to {:g}", stretch);
  if (shrink > kLimit) return fmt::format("degenerate: it scales lengths by as little as {:g}", 1.f / shrink);
  if (shift > kLimit) return fmt::format("overflow: it moves the origin {:g} away", shift);
  return "";
}

}  // namespace

const std::map<std::string, SceneParser::Handler, std::less<>>& SceneParser::handlers() {
  static const std::map<std::string, Handler, std::less<>> table = {
      {"Include", &SceneParser::include},
      {"Import", &SceneParser::import},
      {"AttributeBegin", &SceneParser::attribute_begin},
      {"AttributeEnd", &SceneParser::attribute_end},
      {"TransformBegin", &SceneParser::transform_begin},
      {"TransformEnd", &SceneParser::transform_end},
      {"Attribute", &SceneParser::attribute},
      {"Translate", &SceneParser::translate},
      {"Rotate", &SceneParser::rotate},
      {"Scale", &SceneParser::scale},
      {"LookAt", &SceneParser::look_at},
      {"Transform", &SceneParser::transform},
      {"ConcatTransform", &SceneParser::concat_transform},
      {"Identity", &SceneParser::identity},
      {"CoordinateSystem", &SceneParser::coordinate_system},
      {"CoordSysTransform", &SceneParser::coord_sys_transform},
      {"ReverseOrientation", &SceneParser::reverse_orientation},
      {"ActiveTransform", &SceneParser::active_transform},
      {"TransformTimes", &SceneParser::transform_times},
      {"Camera", &SceneParser::camera},
      {"Film", &SceneParser::film},
      {"Sampler", &SceneParser::sampler},
      {"Integrator", &SceneParser::integrator},
      {"PixelFilter", &SceneParser::pixel_filter},
      {"Accelerator", &SceneParser::accelerator},
      {"ColorSpace", &SceneParser::color_space},
      {"Option", &SceneParser::option},
      {"WorldBegin", &SceneParser::world_begin},
      {"WorldEnd", &SceneParser::world_end},
      {"LightSource", &SceneParser::light_source},
      {"AreaLightSource", &SceneParser::area_light_source},
      {"Material", &SceneParser::material},
      {"MakeNamedMaterial", &SceneParser::make_named_material},
      {"NamedMaterial", &SceneParser::named_material},
      {"Texture", &SceneParser::texture},
      {"Shape", &SceneParser::shape},
      {"ObjectBegin", &SceneParser::object_begin},
      {"ObjectEnd", &SceneParser::object_end},
      {"ObjectInstance", &SceneParser::object_instance},
      {"MakeNamedMedium", &SceneParser::make_named_medium},
      {"MediumInterface", &SceneParser::medium_interface},
  };
  return table;
}

// Attribute values are defaults for a whole class of directives, so (as in pbrt-v4) one a
// particular plugin does not read is not an error: they join the list already marked used.
ParameterList SceneParser::with_attributes(ParameterList list, const std::vector<Param>& attributes) {
  for (const Param& a : attributes) {
    if (list.has(a.name)) continue;
    Param copy = a;
    copy.used = true;
    list.add(std::move(copy));
  }
  return list;
}

// ---------------------------------------------------------------------------------------
// Blocks and transforms

void SceneParser::require_world(const SourceLoc& loc, const char* directive) const {
  if (!in_world_) fail(loc, "{} is only allowed after WorldBegin", directive);
}

void SceneParser::require_options(const SourceLoc& loc, const char* directive) const {
  if (in_world_) fail(loc, "{} is not allowed after WorldBegin (it sets a rendering option)", directive);
}

void SceneParser::note_option(const SourceLoc& loc, const char* directive) {
  auto [it, first] = options_seen_.emplace(directive, loc);
  if (!first) warn(loc, fmt::format("{} replaces the one given at {}", directive, it->second.to_string()));
  it->second = loc;
}

void SceneParser::apply(const SourceLoc& loc, const char* directive, const Transform& t, bool replace) {
  if (replace) state_.singular_at.reset();
  // Still singular after anything but a replacement (a product's rank cannot grow).
  if (state_.singular_at) return;
  for (int i = 0; i < 2; ++i) {
    if (!state_.active[i]) continue;
    Transform r = replace ? t : state_.ctm[i] * t;
    if (!is_finite(r.matrix()) || !is_finite(r.inverse_matrix()) || glm::determinant(glm::dmat4(r.matrix())) == 0.0)
      fail(loc, "{} makes the current transform singular or non-finite", directive);
    std::string why = overflow_reason(r);
    if (!why.empty())
      fail(loc,
           "{} makes the current transform {} (lengths between 1e-18 and 1e18 keep their squares in "
           "single precision)",
           directive, why);
    state_.ctm[i] = r;
  }
}

Transform SceneParser::current_transform(const SourceLoc& loc, const char* directive) const {
  if (state_.singular_at)
    fail(loc,
         "{}: the current transform is singular (made so at {}); only shapes may stand under it (they are dropped)",
         directive, state_.singular_at->to_string());
  // pbrt-v4 warns the same way for lights, textures and media (scene.cpp): they do not move.
  if (!(state_.ctm[0] == state_.ctm[1]))
    warn(loc, fmt::format("{}: an animated transform is not supported here (as in pbrt-v4); the start-time "
                          "transform is used",
                          directive));
  return state_.ctm[0];
}

TransformPair SceneParser::current_transforms(const SourceLoc& loc, const char* directive, bool* animated) const {
  if (state_.singular_at)
    fail(loc,
         "{}: the current transform is singular (made so at {}); only shapes may stand under it (they are dropped)",
         directive, state_.singular_at->to_string());
  *animated = !(state_.ctm[0] == state_.ctm[1]);
  if (*animated) {
    try {
      AnimatedTransform check(state_.ctm[0], desc_.transform_start_time, state_.ctm[1], desc_.transform_end_time);
    } catch (const std::domain_error& e) {
      fail(loc, "{}: the start and end transforms cannot be interpolated: {}", directive, e.what());
    }
  }
  return state_.ctm;
}

void SceneParser::push_block(const SourceLoc& loc, const char* directive) {
  blocks_.push_back(OpenBlock{directive, loc, state_});
}

void SceneParser::pop_block(const SourceLoc& loc, const char* directive, const char* opener) {
  if (blocks_.empty()) fail(loc, "{} without a matching {}", directive, opener);
  const OpenBlock& b = blocks_.back();
  if (b.directive != opener) fail(loc, "{} does not match the {} at {}", directive, b.directive, b.loc.to_string());
  if (b.directive == "TransformBegin") {
    // pbrt-v3 semantics: TransformEnd restores the transform only.
    state_.ctm = b.saved.ctm;
    state_.active = b.saved.active;
  } else {
    state_ = b.saved;
  }
  blocks_.pop_back();
}

void SceneParser::attribute_begin(Tokenizer&, const SourceLoc& loc) {
  require_world(loc, "AttributeBegin");
  push_block(loc, "AttributeBegin");
}

void SceneParser::attribute_end(Tokenizer&, const SourceLoc& loc) {
  require_world(loc, "AttributeEnd");
  pop_block(loc, "AttributeEnd", "AttributeBegin");
}

void SceneParser::transform_begin(Tokenizer&, const SourceLoc& loc) {
  if (!warned_transform_begin_)
    warn_deprecated(loc, "TransformBegin/TransformEnd are deprecated (pbrt-v3); use AttributeBegin/AttributeEnd");
  warned_transform_begin_ = true;
  push_block(loc, "TransformBegin");
}

void SceneParser::transform_end(Tokenizer&, const SourceLoc& loc) { pop_block(loc, "TransformEnd", "TransformBegin"); }

void SceneParser::attribute(Tokenizer& tok, const SourceLoc& loc) {
  SourceLoc target_loc;
  std::string target = read_name(tok, "Attribute", "target", &target_loc);
  ParameterList params = read_parameter_list(tok, loc, desc_.search_dir);
  std::vector<Param>* list = target == "shape"      ? &state_.shape_attributes
                             : target == "light"    ? &state_.light_attributes
                             : target == "material" ? &state_.material_attributes
                             : target == "texture"  ? &state_.texture_attributes
                                                    : nullptr;
  if (target == "medium") {
    warn(loc, "Attribute \"medium\" (defaults for MakeNamedMedium) is not supported; ignored");
    return;
  }
  if (!list)
    fail(target_loc,
         "Attribute: unknown target \"{}\"; must be \"shape\", \"light\", \"material\", \"medium\" or \"texture\"{}",
         target, hint_suffix(target, {"shape", "light", "material", "medium", "texture"}));
  for (const Param& p : params.params()) {
    std::erase_if(*list, [&](const Param& old) { return old.name == p.name; });
    list->push_back(p);
  }
}

void SceneParser::translate(Tokenizer& tok, const SourceLoc& loc) {
  std::vector<float> v = read_numbers(tok, "Translate", 3);
  apply(loc, "Translate", eyetrace::translate(Vec3(v[0], v[1], v[2])));
}

void SceneParser::rotate(Tokenizer& tok, const SourceLoc& loc) {
  std::vector<float> v = read_numbers(tok, "Rotate", 4);
  Vec3 axis(v[1], v[2], v[3]);
  if (axis == Vec3(0.f)) fail(loc, "Rotate: the rotation axis is the zero vector");
  apply(loc, "Rotate", eyetrace::rotate(v[0], axis));
}

void SceneParser::scale(Tokenizer& tok, const SourceLoc& loc) {
  std::vector<float> v = read_numbers(tok, "Scale", 3);
  if (v[0] == 0.f || v[1] == 0.f || v[2] == 0.f) fail(loc, "Scale: a zero factor makes the transform singular");
  apply(loc, "Scale", eyetrace::scale(Vec3(v[0], v[1], v[2])));
}

void SceneParser::look_at(Tokenizer& tok, const SourceLoc& loc) {
  std::vector<float> v = read_numbers(tok, "LookAt", 9);
  Transform t;
  try {
    t = eyetrace::look_at(Vec3(v[0], v[1], v[2]), Vec3(v[3], v[4], v[5]), Vec3(v[6], v[7], v[8]));
  } catch (const std::domain_error& e) {
    fail(loc, "LookAt: {}", e.what());
  }
  apply(loc, "LookAt", t);
}

void SceneParser::matrix_directive(Tokenizer& tok, const SourceLoc& loc, const char* directive, bool replace) {
  // pbrt-v4 requires the brackets; pbrt-v3 files sometimes omit them, which is unambiguous.
  bool bracketed = tok.peek().kind == TokenKind::OpenBracket;
  if (bracketed) tok.next();
  std::vector<float> v = read_numbers(tok, directive, 16);
  if (bracketed) {
    Token close = tok.next();
    if (close.kind != TokenKind::CloseBracket)
      fail(tok.loc(close), "{}: expected ']' after 16 numbers, got {}", directive, close.describe());
  }
  // pbrt reads the 16 values row-major and transposes; glm's column-major read is the same.
  Transform t;
  try {
    t = Transform(glm::make_mat4(v.data()));
  } catch (const std::domain_error&) {
    // Exporters write an all-zero row for an object scaled to nothing. What it maps is flat (a
    // plane, a line, a point) and has no normal: pbrt-v4 aborts on the NaN normal when a ray
    // hits it. Here the shapes under it are dropped, with a warning at each (shape()).
    if (!replace && state_.singular_at) return;
    state_.singular_at = loc;
    return;
  }
  apply(loc, directive, t, replace);
}

void SceneParser::coordinate_system(Tokenizer& tok, const SourceLoc&) {
  coordinate_systems_[read_name(tok, "CoordinateSystem", "name")] = state_.ctm;
}

void SceneParser::coord_sys_transform(Tokenizer& tok, const SourceLoc& loc) {
  std::string name = read_name(tok, "CoordSysTransform", "name");
  auto it = coordinate_systems_.find(name);
  if (it == coordinate_systems_.end())
    fail(loc, "CoordSysTransform: no coordinate system named \"{}\"{}", name,
         hint_suffix(name, keys_of(coordinate_systems_)));
  state_.ctm = it->second;  // both times, as pbrt-v4 does
  state_.singular_at.reset();
}

void SceneParser::reverse_orientation(Tokenizer&, const SourceLoc& loc) {
  require_world(loc, "ReverseOrientation");
  state_.reverse_orientation = !state_.reverse_orientation;
}

void SceneParser::active_transform(Tokenizer& tok, const SourceLoc&) {
  Token t = tok.next();
  if (t.kind == TokenKind::Word && t.text == "StartTime")
    state_.active = {true, false};
  else if (t.kind == TokenKind::Word && t.text == "EndTime")
    state_.active = {false, true};
  else if (t.kind == TokenKind::Word && t.text == "All")
    state_.active = {true, true};
  else
    fail(tok.loc(t), "ActiveTransform: expected StartTime, EndTime or All, got {}", t.describe());
}

void SceneParser::transform_times(Tokenizer& tok, const SourceLoc& loc) {
  require_options(loc, "TransformTimes");
  // pbrt-v4 accepts any two numbers: equal or reversed times make the motion a jump from the
  // start to the end transform just after the start time (AnimatedTransform::fraction).
  std::vector<float> v = read_numbers(tok, "TransformTimes", 2);
  desc_.transform_start_time = v[0];
  desc_.transform_end_time = v[1];
}

// ---------------------------------------------------------------------------------------
// Rendering options

void SceneParser::camera(Tokenizer& tok, const SourceLoc& loc) {
  require_options(loc, "Camera");
  SceneEntity e = read_entity(tok, loc, "Camera");
  note_option(loc, "Camera");
  bool animated = false;
  TransformPair camera_from_world = current_transforms(loc, "Camera", &animated);
  static_cast<SceneEntity&>(desc_.camera) = std::move(e);
  desc_.camera.world_from_camera = camera_from_world[0].inverse();
  desc_.camera.world_from_camera_end = camera_from_world[1].inverse();
  desc_.camera.animated = animated;
  desc_.camera.transform_start_time = desc_.transform_start_time;
  desc_.camera.transform_end_time = desc_.transform_end_time;
  desc_.has_camera = true;
  desc_.camera.media = state_.media;
  // pbrt-v4: the named coordinate system "camera" is the camera's world_from_camera.
  coordinate_systems_["camera"] = {state_.ctm[0].inverse(), state_.ctm[1].inverse()};
}

void SceneParser::option_entity(Tokenizer& tok, const SourceLoc& loc, const char* directive, SceneEntity& out) {
  require_options(loc, directive);
  SceneEntity e = read_entity(tok, loc, directive);
  note_option(loc, directive);
  out = std::move(e);
}

void SceneParser::accelerator(Tokenizer& tok, const SourceLoc& loc) {
  require_options(loc, "Accelerator");
  SceneEntity e = read_entity(tok, loc, "Accelerator");
  warn(loc, fmt::format("Accelerator \"{}\" ignored: eyetrace always uses Embree's BVH", e.name));
}

void SceneParser::color_space(Tokenizer& tok, const SourceLoc& loc) {
  SourceLoc name_loc;
  std::string name = read_name(tok, "ColorSpace", "name", &name_loc);
  const std::vector<std::string> known = {"srgb", "aces2065-1", "rec2020", "dci-p3"};
  if (std::find(known.begin(), known.end(), name) == known.end())
    fail(name_loc, "ColorSpace: unknown color space \"{}\"{}", name, hint_suffix(name, known));
  if (in_world_ && name != desc_.color_space)
    warn(loc,
         fmt::format("per-object color spaces are not supported; ColorSpace \"{}\" applies to the whole scene", name));
  desc_.color_space = name;
  color_space_set_ = true;
}

void SceneParser::option(Tokenizer& tok, const SourceLoc& loc) {
  Token decl = tok.next();
  if (decl.kind != TokenKind::String)
    fail(tok.loc(decl), "Option: expected a quoted \"type name\", got {}", decl.describe());
  Param p = read_parameter(tok, decl, desc_.search_dir);
  SceneEntity e{p.name, ParameterList(loc), loc};
  e.params.add(std::move(p));
  desc_.options.push_back(std::move(e));
}

void SceneParser::world_begin(Tokenizer&, const SourceLoc& loc) {
  require_options(loc, "WorldBegin");
  in_world_ = true;
  // Without a Camera directive (a camera given on the command line, as for the eye models) the
  // camera sits where one declared here would: in the outside medium current now.
  if (!desc_.has_camera) desc_.camera.media = state_.media;
  state_.ctm = {Transform(), Transform()};
  state_.singular_at.reset();
  state_.active = {true, true};
  coordinate_systems_["world"] = state_.ctm;
}

void SceneParser::world_end(Tokenizer&, const SourceLoc& loc) {
  warn(loc, "WorldEnd is pbrt-v3 syntax and is ignored (pbrt-v4 scenes end at the end of the file)");
}

// ---------------------------------------------------------------------------------------
// The world

void SceneParser::light_source(Tokenizer& tok, const SourceLoc& loc) {
  require_world(loc, "LightSource");
  TransformedEntity light;
  static_cast<SceneEntity&>(light) = read_entity(tok, loc, "LightSource");
  light.params = with_attributes(std::move(light.params), state_.light_attributes);
  light.world_from_object = current_transform(loc, "LightSource");
  light.reverse_orientation = state_.reverse_orientation;
  if (current_object_)
    warn(loc, fmt::format("LightSource inside ObjectBegin \"{}\" is not instanced; it is placed once, "
                          "with the transform at its definition",
                          *current_object_));
  desc_.lights.push_back(std::move(light));
}

void SceneParser::area_light_source(Tokenizer& tok, const SourceLoc& loc) {
  require_world(loc, "AreaLightSource");
  TransformedEntity light;
  static_cast<SceneEntity&>(light) = read_entity(tok, loc, "AreaLightSource");
  light.params = with_attributes(std::move(light.params), state_.light_attributes);
  light.world_from_object = current_transform(loc, "AreaLightSource");
  light.reverse_orientation = state_.reverse_orientation;
  desc_.area_lights.push_back(std::move(light));
  state_.area_light = area_light_base_ + int(desc_.area_lights.size()) - 1;
}

void SceneParser::material(Tokenizer& tok, const SourceLoc& loc) {
  require_world(loc, "Material");
  SceneEntity m = read_entity(tok, loc, "Material");
  m.params = with_attributes(std::move(m.params), state_.material_attributes);
  desc_.materials.push_back(std::move(m));
  state_.material = MaterialRef{material_base_ + int(desc_.materials.size()) - 1, ""};
}

void SceneParser::make_named_material(Tokenizer& tok, const SourceLoc& loc) {
  require_world(loc, "MakeNamedMaterial");
  std::string name = read_name(tok, "MakeNamedMaterial", "material name");
  ParameterList params = with_attributes(read_parameter_list(tok, loc, desc_.search_dir), state_.material_attributes);
  if (auto it = named_material_locs_.find(name); it != named_material_locs_.end())
    fail(loc, "MakeNamedMaterial: material \"{}\" is already defined at {}", name, it->second.to_string());
  if (!params.has("type"))
    fail(loc, "MakeNamedMaterial \"{}\": missing the \"string type\" parameter (e.g. \"diffuse\")", name);
  std::string type = params.get_string("type", "");  // marks it used
  named_material_locs_[name] = loc;
  desc_.named_materials[name] = SceneEntity{type, std::move(params), loc};
}

void SceneParser::named_material(Tokenizer& tok, const SourceLoc& loc) {
  require_world(loc, "NamedMaterial");
  std::string name = read_name(tok, "NamedMaterial", "material name");
  // Resolved where a shape uses it, once the whole scene is read (scene_builder.cpp): pbrt-v4 lets
  // NamedMaterial come before the MakeNamedMaterial it names (contemporary-bathroom does).
  state_.material = MaterialRef{-1, name};
}

void SceneParser::texture(Tokenizer& tok, const SourceLoc& loc) {
  require_world(loc, "Texture");
  TextureEntity t;
  SourceLoc type_loc;
  t.texture_name = read_name(tok, "Texture", "texture name");
  t.value_type = read_name(tok, "Texture", "value type", &type_loc);
  t.name = read_name(tok, "Texture", "texture class");
  t.params = with_attributes(read_parameter_list(tok, loc, desc_.search_dir), state_.texture_attributes);
  t.loc = loc;
  if (t.value_type != "float" && t.value_type != "spectrum")
    fail(type_loc, "Texture \"{}\": value type \"{}\" must be \"float\" or \"spectrum\"{}", t.texture_name,
         t.value_type, t.value_type == "color" ? " (\"color\" is pbrt-v3 syntax for \"spectrum\")" : "");
  auto [it, fresh] = texture_names_.emplace(std::pair(t.texture_name, t.value_type), loc);
  if (!fresh)
    fail(loc, "Texture: {} texture \"{}\" is already defined at {}", t.value_type, t.texture_name,
         it->second.to_string());
  t.world_from_object = current_transform(loc, "Texture");
  t.reverse_orientation = state_.reverse_orientation;
  desc_.textures.push_back(std::move(t));
}

void SceneParser::shape(Tokenizer& tok, const SourceLoc& loc) {
  require_world(loc, "Shape");
  ShapeEntity s;
  static_cast<SceneEntity&>(s) = read_entity(tok, loc, "Shape");
  if (state_.singular_at) {
    warn(loc, fmt::format("Shape \"{}\" dropped: the transform made singular at {} maps it to something flat, "
                          "without a normal",
                          s.name, state_.singular_at->to_string()));
    return;
  }
  s.params = with_attributes(std::move(s.params), state_.shape_attributes);
  TransformPair ctm = current_transforms(loc, "Shape", &s.animated);
  s.world_from_object = ctm[0];
  s.world_from_object_end = ctm[1];
  // pbrt-v4 drops the area light of a shape inside ObjectBegin (below) before it could move.
  if (s.animated && state_.area_light >= 0 && !current_object_)
    fail(loc,
         "Shape \"{}\": animated area lights are not supported (as in pbrt-v4): its start and end transforms "
         "differ",
         s.name);
  s.reverse_orientation = state_.reverse_orientation;
  s.material = state_.material;
  s.area_light = state_.area_light;
  s.media = state_.media;
  if (!current_object_) {
    desc_.shapes.push_back(std::move(s));
    return;
  }
  if (s.area_light >= 0) {
    warn(loc, "area lights are not supported with object instancing; this shape will not emit");
    s.area_light = -1;
  }
  desc_.instances[*current_object_].shapes.push_back(std::move(s));
}

// pbrt-v4 instancing: shapes inside ObjectBegin keep the full transform current at their
// definition; ObjectInstance records the transform current at the use, and the builder
// places each shape at world_from_instance * world_from_object.
void SceneParser::object_begin(Tokenizer& tok, const SourceLoc& loc) {
  require_world(loc, "ObjectBegin");
  std::string name = read_name(tok, "ObjectBegin", "object name");
  if (current_object_)
    fail(loc, "ObjectBegin \"{}\" inside the definition of \"{}\" (instances cannot nest)", name, *current_object_);
  if (auto it = instance_locs_.find(name); it != instance_locs_.end())
    fail(loc, "ObjectBegin: object \"{}\" is already defined at {}", name, it->second.to_string());
  push_block(loc, "ObjectBegin");
  desc_.instances[name] = InstanceDefinition{name, loc, {}};
  instance_locs_[name] = loc;
  current_object_ = name;
}

void SceneParser::object_end(Tokenizer&, const SourceLoc& loc) {
  require_world(loc, "ObjectEnd");
  if (is_import_ && current_object_ && blocks_.empty())
    fail(loc,
         "ObjectEnd in an imported file cannot end the ObjectBegin \"{}\" of the file that imports it (as in "
         "pbrt-v4)",
         *current_object_);
  pop_block(loc, "ObjectEnd", "ObjectBegin");
  current_object_.reset();
}

void SceneParser::object_instance(Tokenizer& tok, const SourceLoc& loc) {
  require_world(loc, "ObjectInstance");
  std::string name = read_name(tok, "ObjectInstance", "object name");
  if (current_object_)
    fail(loc, "ObjectInstance \"{}\" inside the definition of \"{}\" (instances cannot nest)", name, *current_object_);
  if (!instance_locs_.count(name))
    fail(loc, "ObjectInstance: no object named \"{}\" has been defined with ObjectBegin{}", name,
         hint_suffix(name, keys_of(instance_locs_)));
  if (state_.singular_at) {
    warn(loc, fmt::format("ObjectInstance \"{}\" dropped: the transform made singular at {} maps it to something "
                          "flat, without a normal",
                          name, state_.singular_at->to_string()));
    return;
  }
  bool animated = false;
  TransformPair ctm = current_transforms(loc, "ObjectInstance", &animated);
  desc_.instance_uses.push_back(InstanceUse{name, loc, std::make_shared<const Transform>(ctm[0]),
                                            animated ? std::make_shared<const Transform>(ctm[1]) : nullptr});
}

void SceneParser::make_named_medium(Tokenizer& tok, const SourceLoc& loc) {
  std::string name = read_name(tok, "MakeNamedMedium", "medium name");
  ParameterList params = read_parameter_list(tok, loc, desc_.search_dir);
  if (auto it = medium_locs_.find(name); it != medium_locs_.end())
    fail(loc, "MakeNamedMedium: medium \"{}\" is already defined at {}", name, it->second.to_string());
  if (!params.has("type"))
    fail(loc, "MakeNamedMedium \"{}\": missing the \"string type\" parameter (e.g. \"homogeneous\")", name);
  TransformedEntity m;
  m.name = params.get_string("type", "");  // marks it used
  m.params = std::move(params);
  m.loc = loc;
  m.world_from_object = current_transform(loc, "MakeNamedMedium");
  desc_.media[name] = std::move(m);
  medium_locs_[name] = loc;
}

// Names only: pbrt-v4 resolves them when the scene is built, so a medium may be defined after
// its first use; the builder reports unknown names at this directive's line.
void SceneParser::medium_interface(Tokenizer& tok, const SourceLoc& loc) {
  std::string inside = read_name(tok, "MediumInterface", "medium name");
  std::string outside = inside;
  if (tok.peek().kind == TokenKind::String) outside = tok.next().string_value();
  state_.media = MediumNames{inside, outside, loc};
}

}  // namespace eyetrace::parsing
