#include "scene/scene_builder.h"

#include <cctype>
#include <filesystem>
#include <set>

#include "scene/registry.h"
#include "scene/scene_files.h"

namespace eyetrace {

namespace {

struct FilmSettings {
  bool gbuffer = false;
  bool gbuffer_world = false;  // positions and normals in world space (else camera space)
  IVec2 resolution{1280, 720};
  PixelBounds bounds;
  std::string filename = "pbrt.exr";
  float scale = 1.f;
  SpectralBuckets buckets;  // count 0: an RGB film
  FilmResponse response;
};

// Every camera PixelSensor knows, comma separated.
std::string camera_names() {
  std::string names;
  for (const std::string& n : PixelSensor::camera_names()) names += (names.empty() ? "" : ", ") + n;
  return names;
}

// The parameters every film takes (pbrt-v4's FilmBaseParameters, PixelSensor and RGB film).
std::vector<ParamSpec> film_base_params() {
  return {
      param::integer("xresolution", 1280).range(1, 1 << 15).with_unit("pixels"),
      param::integer("yresolution", 720).range(1, 1 << 15).with_unit("pixels"),
      param::reals("cropwindow").size(4).range(0, 1).describe("x0 x1 y0 y1, fractions of the image"),
      param::integers("pixelbounds").size(4).describe("x0 x1 y0 y1, pixels (a crop window takes precedence)"),
      param::string("filename", "pbrt.exr").describe("output image (a command-line output replaces it)"),
      param::real("iso", 100).above(0).describe("the image is scaled by iso/100 × exposure time"),
      param::real("exposuretime", 1).above(0).with_unit("s"),
      param::real("scale", 1)
          .above(0)
          .describe("multiplies the image (pbrt-v3 and early pbrt-v4; today's pbrt-v4 refuses it)"),
      param::boolean("savefp16", true).describe("ignored"),
      param::real("maxcomponentvalue")
          .above(0)
          .describe("each sample's sensor RGB (× iso/100 × exposuretime) scaled so that its largest component is at "
                    "most this (pbrt-v4's clamp; unset: no clamp)"),
      param::real("diagonal", 35).with_unit("mm").describe("ignored (the realistic camera has its own)"),
      param::string("sensor", "cie1931").describe("cie1931 (XYZ) or a camera of pbrt-v4's: " + camera_names()),
      param::real("whitebalance", 0)
          .at_least(0)
          .with_unit("K")
          .describe("colour temperature to balance for (Bradford); 0: none for cie1931, 6500 for a camera"),
  };
}

}  // namespace

const PluginSpec& film_spec() {
  static const PluginSpec spec{
      "Film", "the image: its size, crop window, output file and exposure",
      "`savefp16` and `diagonal` are accepted and ignored. The exposure time is the camera's shutter interval "
      "(`shutterclose` - `shutteropen`, as pbrt-v4) times `exposuretime` (eyetrace's own, pbrt-v4 has none). "
      "The sensor's XYZ matrix is fitted over 380-780 nm of D-series illuminant (pbrt-v4: 300-830 nm).",
      film_base_params()};
  return spec;
}

const PluginSpec& spectral_film_spec() {
  static const PluginSpec spec{
      "Film",
      "the `rgb` film's R, G, B plus one channel per wavelength bucket: the mean spectral radiance over the bucket "
      "(docs/spectral.md)",
      "Default range 400–700 nm (pbrt-v4: 360–830 nm). Wavelengths are drawn as for `rgb` (pbrt-v4's visible "
      "density over 360–830 nm), not uniformly over [lambdamin, lambdamax], so R, G, B are the `rgb` film's. "
      "EXR only; always float32 (`savefp16` ignored).",
      film_base_params() + std::vector<ParamSpec>{
                               param::integer("nbuckets", 16)
                                   .range(1, SpectralBuckets::kMaxCount)
                                   .describe("wavelength buckets of equal width"),
                               param::real("lambdamin", 400)
                                   .range(kLambdaMin, kLambdaMax)
                                   .with_unit("nm")
                                   .describe("short end of the first bucket"),
                               param::real("lambdamax", 700)
                                   .range(kLambdaMin, kLambdaMax)
                                   .with_unit("nm")
                                   .describe("long end of the last bucket; above lambdamin"),
                           }};
  return spec;
}

const PluginSpec& gbuffer_film_spec() {
  static const PluginSpec spec{
      "Film",
      "the `rgb` film's R, G, B plus pbrt-v4's auxiliary channels: Albedo, P, dzdx, dzdy, N, Ns, u, v, Variance, "
      "RelativeVariance (src/render/gbuffer.h)",
      "Variance is of the output colour, pbrt-v4's of the sensor RGB. EXR only; always float32 (`savefp16` ignored). "
      "Cannot be "
      "checkpointed, resumed or rendered over several MPI processes.",
      film_base_params() + std::vector<ParamSpec>{param::string("coordinatesystem", "camera")
                                                      .in({"camera", "world"})
                                                      .describe("the space of P, N and Ns")}};
  return spec;
}

namespace {

bool has_extension(const std::string& path, const std::string& ext) {
  std::string e = std::filesystem::path(path).extension().string();
  for (auto& c : e) c = char(std::tolower(static_cast<unsigned char>(c)));
  return e == ext;
}

// pbrt-v4 takes the exposure time from the camera's shutter, shutterclose - shutteropen (its
// BasicScene reads them from the camera's parameters for the film); eyetrace's own Film
// "exposuretime" multiplies it. A shutter that never opens is an error, as in pbrt-v4.
float shutter_seconds(const SceneEntity& camera) {
  auto value = [&](const char* name, float def) {
    const Param* p = camera.params.find(name);
    return p && p->numbers.size() == 1 ? float(p->numbers[0]) : def;
  };
  const float seconds = value("shutterclose", 1.f) - value("shutteropen", 0.f);
  if (!(seconds > 0.f)) {
    const Param* close = camera.params.find("shutterclose");
    fail(close ? close->loc : camera.loc,
         "parameter \"shutterclose\": the shutter never opens (shutterclose - shutteropen = {}): the image would be "
         "black",
         seconds);
  }
  return seconds;
}

// The pixel sensor and clamp (pbrt-v4's PixelSensor::Create and RGBFilm::Create): cie1931 is
// white balanced only when given a temperature, a camera at 6500 K unless given one.
FilmResponse read_film_response(const PluginParams& p, float shutter) {
  FilmResponse r;
  r.imaging_ratio = p.get_float("iso") / 100.f * p.get_float("exposuretime") * shutter;
  if (p.has("maxcomponentvalue")) r.max_component = p.get_float("maxcomponentvalue");
  const std::string name = p.get_string("sensor");
  const double kelvin = p.get_float("whitebalance");
  std::optional<PixelSensor> sensor;
  if (name == "cie1931") {
    if (kelvin > 0.0) sensor = PixelSensor::cie1931(kelvin);
  } else {
    sensor = PixelSensor::camera(name, kelvin > 0.0 ? kelvin : 6500.0);
    if (!sensor) p.fail("sensor", fmt::format("unknown sensor \"{}\"; known: cie1931, {}", name, camera_names()));
  }
  if (sensor && !sensor->finite())
    p.fail("whitebalance",
           fmt::format("{} K: a light this cold has no power in the visible range to balance for", kelvin));
  if (sensor) r.sensor = std::make_shared<PixelSensor>(std::move(*sensor));
  return r;
}

// The camera the render uses: the command line's, else the scene's.
const SceneEntity& scene_camera(const SceneDescription& desc, const RenderOverrides& o) {
  return o.camera ? *o.camera : static_cast<const SceneEntity&>(desc.camera);
}

FilmSettings read_film(const SceneEntity& film, const SceneEntity& camera, const RenderOverrides& o) {
  if (film.name != "rgb" && film.name != "gbuffer" && film.name != "spectral")
    fail(film.loc, "unsupported film \"{}\"; eyetrace supports: rgb, spectral", film.name);
  const bool spectral = film.name == "spectral", gbuffer = film.name == "gbuffer";
  const PluginParams p(film.params,
                       spectral  ? spectral_film_spec()
                       : gbuffer ? gbuffer_film_spec()
                                 : film_spec(),
                       film.name);
  FilmSettings f;
  f.gbuffer = gbuffer;
  if (gbuffer) f.gbuffer_world = p.get_string("coordinatesystem") == "world";
  f.resolution = IVec2(p.get_int("xresolution"), p.get_int("yresolution"));
  if (o.resolution) {  // --resolution: checked here, the scene's values by the table
    f.resolution = *o.resolution;
    const int kMaxSide = 1 << 15;
    if (f.resolution.x < 1 || f.resolution.y < 1 || f.resolution.x > kMaxSide || f.resolution.y > kMaxSide)
      throw_error(
          fmt::format("--resolution {}x{} is outside 1..{} per side", f.resolution.x, f.resolution.y, kMaxSide));
  }
  Vec4 crop(0.f, 1.f, 0.f, 1.f);
  std::vector<float> cw = p.get_floats("cropwindow");
  if (!cw.empty()) crop = Vec4(cw[0], cw[1], cw[2], cw[3]);
  if (o.crop) crop = *o.crop;
  if (!(crop[0] >= 0 && crop[0] < crop[1] && crop[1] <= 1 && crop[2] >= 0 && crop[2] < crop[3] && crop[3] <= 1))
    p.fail("cropwindow", "needs 0 <= x0 < x1 <= 1 and 0 <= y0 < y1 <= 1");
  f.bounds = crop_to_pixels(f.resolution, crop);
  std::vector<int> pb = p.get_ints("pixelbounds");
  if (!pb.empty()) {
    if (pb[0] < 0 || pb[1] > f.resolution.x || pb[2] < 0 || pb[3] > f.resolution.y || pb[0] >= pb[1] || pb[2] >= pb[3])
      p.fail("pixelbounds", "needs x0 < x1 <= xresolution and y0 < y1 <= yresolution");
    if (!o.crop) f.bounds = PixelBounds{IVec2(pb[0], pb[2]), IVec2(pb[1], pb[3])};
  }
  if (f.bounds.area() == 0) p.fail("cropwindow", "the crop window covers no pixel");
  f.filename = p.get_string("filename");
  const float shutter = shutter_seconds(camera);
  f.response = read_film_response(p, shutter);
  f.scale = p.get_float("iso") / 100.f * p.get_float("exposuretime") * shutter * p.get_float("scale");
  if (spectral) {
    f.buckets.count = p.get_int("nbuckets");
    f.buckets.lambda_min = p.get_float("lambdamin");
    f.buckets.lambda_max = p.get_float("lambdamax");
    if (!(f.buckets.lambda_min < f.buckets.lambda_max))
      p.fail(p.has("lambdamax") ? "lambdamax" : "lambdamin",
             fmt::format("lambdamin {} nm must be below lambdamax {} nm", f.buckets.lambda_min, f.buckets.lambda_max));
  }
  if (spectral || gbuffer) {
    // As pbrt-v4: the spectral and gbuffer films write EXR only; the image that would be written
    // is checked, the command line's if it replaces the scene's.
    if (!o.output.empty() && !has_extension(o.output, ".exr"))
      throw_parameter_error({}, "--output",
                            fmt::format("\"{}\": the {} film (Film \"{}\" at {}) writes EXR only", o.output, film.name,
                                        film.name, film.loc.to_string()));
    if (o.output.empty() && !has_extension(f.filename, ".exr"))
      p.fail("filename", fmt::format("\"{}\": the {} film writes EXR only (use a .exr name)", f.filename, film.name));
  }
  return f;
}

class Builder {
 public:
  Builder(const SceneDescription& desc, RenderSetup& setup, bool keep_going)
      : desc_(desc), setup_(setup), keep_going_(keep_going) {}

  // Every texture, shape, instance and light is tried and its errors collected; textures
  // first, and a failed texture stops the build there, since the materials naming it would
  // only repeat the error.
  void build_world() {
    setup_.textures = std::make_unique<TextureStore>();
    setup_.scene = std::make_unique<Scene>();
    for (const TextureEntity& t : desc_.textures)
      if (!attempt([&] { build_texture(t); }) && keep_going_) add_stand_in(t);
    if (!keep_going_) errors_.throw_if_any();
    if (keep_going_) check_every_material();
    for (const auto& [name, m] : desc_.media) attempt([&] { build_medium(name, m); });
    attempt([&] { setup_.scene->set_camera_medium(medium(desc_.camera.media.outside, desc_.camera.media.loc)); });
    for (const ShapeEntity& s : desc_.shapes) attempt([&] { add_shape(s); });
    std::set<std::string> used, failed_objects;
    for (const InstanceUse& u : desc_.instance_uses) used.insert(u.name);
    for (const auto& [name, def] : desc_.instances) {
      // No ray can reach an object that is never instanced: building its shapes and BVH
      // would only cost time and memory.
      if (used.count(name)) {
        if (!build_instance(def)) failed_objects.insert(name);
      } else
        attempt([&] {
          warn(def.loc,
               fmt::format("ObjectBegin \"{}\" is never instanced: not built (its shapes are not checked)", name));
        });
    }
    for (const InstanceUse& u : desc_.instance_uses)
      attempt([&] {
        // An object whose shapes failed has its errors already: its uses would only repeat them.
        if (failed_objects.count(u.name)) return;
        if (!setup_.scene->has_instance(u.name)) fail(u.loc, "ObjectInstance \"{}\": no such object", u.name);
        if (u.animated())
          setup_.scene->add_instance(u.name, motion(*u.world_from_instance, *u.world_from_instance_end));
        else
          setup_.scene->add_instance(u.name, u.world_from_instance);
        place_moving_members(u);
      });
    for (const TransformedEntity& l : desc_.lights) attempt([&] { add_light(l); });
    errors_.throw_if_any();
    setup_.scene->commit();
    check_light_power();
  }

 private:
  template <typename F>
  bool attempt(F&& f) {
    try {
      f();
      return true;
    } catch (const SceneError& e) {
      errors_.add_all(e.diagnostics());
      return false;
    }
  }

  // A texture that failed (its error is recorded) as a constant, so that the materials naming
  // it are checked for their own errors rather than repeating this one.
  void add_stand_in(const TextureEntity& t) {
    attempt([&] {
      if (t.value_type == "float")
        setup_.textures->add_float(t.texture_name, std::make_unique<ConstantFloatTexture>(0.5f), t.loc);
      else
        setup_.textures->add_spectrum(t.texture_name, std::make_unique<ConstantSpectrumTexture>(RGB(0.5f)), t.loc);
    });
  }

  void add_light(const TransformedEntity& l) {
    LightContext ctx{l.params, l.world_from_object, desc_.search_dir};
    auto light = reg_.lights.at(l.name, l.loc)(ctx);
    light_sources_.emplace_back(light.get(), &l);
    setup_.scene->add_light(std::move(light));
  }

  void build_medium(const std::string& name, const TransformedEntity& m) {
    media_[name] = nullptr;
    MediumContext ctx{m.params, m.world_from_object, desc_.search_dir};
    auto made = reg_.media.at(m.name, m.loc)(ctx);
    media_[name] = setup_.scene->own(std::move(made));
  }

  // A name from MediumInterface ("" is vacuum); `loc` is that directive's.
  const Medium* medium(const std::string& name, const SourceLoc& loc) const {
    if (name.empty()) return nullptr;
    auto it = media_.find(name);
    if (it != media_.end()) return it->second;
    if (desc_.media.count(name)) return nullptr;  // defined, but failed: its error is already reported
    fail(loc, "MediumInterface: no medium named \"{}\" has been defined with MakeNamedMedium{}", name,
         parsing_hint(name));
  }

  std::string parsing_hint(const std::string& name) const {
    std::vector<std::string> names;
    for (const auto& kv : desc_.media) names.push_back(kv.first);
    std::string m = closest_match(name, names);
    return m.empty() ? "" : fmt::format(" (did you mean \"{}\"?)", m);
  }

  void build_texture(const TextureEntity& t) {
    TextureContext ctx{t.params, t.world_from_object, *setup_.textures, desc_.search_dir};
    if (t.value_type == "float") {
      auto tex = reg_.float_textures.at(t.name, t.loc)(ctx);
      setup_.textures->add_float(t.texture_name, std::move(tex), t.loc);
    } else {
      auto tex = reg_.spectrum_textures.at(t.name, t.loc)(ctx);
      setup_.textures->add_spectrum(t.texture_name, std::move(tex), t.loc);
    }
  }

  // Materials are made on first use, so a scene pays only for the ones its shapes reference.
  const Material* material(const MaterialRef& ref, const SourceLoc& loc) {
    const SceneEntity* e = nullptr;
    std::string key;
    if (!ref.name.empty()) {
      auto it = desc_.named_materials.find(ref.name);
      if (it == desc_.named_materials.end()) {
        std::vector<std::string> names;
        for (const auto& [n, m] : desc_.named_materials) names.push_back(n);
        const std::string hint = closest_match(ref.name, names);
        fail(loc, "NamedMaterial \"{}\" is not defined with MakeNamedMaterial{}", ref.name,
             hint.empty() ? "" : fmt::format(" (did you mean \"{}\"?)", hint));
      }
      e = &it->second;
      key = "named:" + ref.name;
    } else if (ref.index >= 0 && size_t(ref.index) < desc_.materials.size()) {
      e = &desc_.materials[ref.index];
      key = fmt::format("index:{}", ref.index);
    } else {
      return nullptr;
    }
    auto it = materials_.find(key);
    if (it != materials_.end()) return it->second;
    // A "mix" names other materials, made here on first use; one that leads back to itself
    // would never finish.
    if (!materials_in_progress_.insert(key).second)
      fail(loc, "material \"{}\" contains itself (through \"mix\")", ref.name.empty() ? key : ref.name);
    struct Done {
      std::set<std::string>& set;
      std::string key;
      ~Done() { set.erase(key); }
    } done{materials_in_progress_, key};
    MaterialContext ctx{e->params, *setup_.textures, desc_.search_dir, [this, e](const std::string& name) {
                          return material(MaterialRef{-1, name}, e->loc);
                        }};
    // pbrt-v4 reads `Material ""` and "none" (deprecated) as "interface": no surface, only the
    // boundary of a medium.
    const std::string& name = e->name.empty() || e->name == "none" ? std::string("interface") : e->name;
    auto m = reg_.materials.at(name, e->loc)(ctx);
    const Material* raw = m ? setup_.scene->own(std::move(m)) : nullptr;
    if (name == "interface") interfaces_.insert(raw);
    materials_[key] = raw;
    return raw;
  }

  // Both transforms were checked by the parser (AnimatedTransform throws for none of them).
  AnimatedTransform motion(const Transform& start, const Transform& end) const {
    return AnimatedTransform(start, desc_.transform_start_time, end, desc_.transform_end_time);
  }

  // `world_from_object`: the shape's own transform, or the identity for a moving shape (made in
  // its object space and moved as a whole, as pbrt-v4's AnimatedPrimitive does).
  std::vector<Primitive> make_primitives(const ShapeEntity& s, bool allow_area_light,
                                         const Transform& world_from_object) {
    ShapeContext ctx{s.params, world_from_object, s.reverse_orientation, desc_.search_dir, setup_.textures.get()};
    auto shapes = reg_.shapes.at(s.name, s.loc)(ctx);
    // A shape with the interface material has no surface: its primitives carry no material, which
    // tells the integrators (and volpath's shadow rays) to pass through it.
    const Material* mat = material(s.material, s.loc);
    if (interfaces_.count(mat)) mat = nullptr;
    const MediumInterface media{medium(s.media.inside, s.media.loc), medium(s.media.outside, s.media.loc)};
    std::vector<Primitive> prims;
    for (auto& shape : shapes) {
      Primitive prim{std::move(shape), mat, nullptr, media};
      if (s.area_light >= 0) {
        if (!allow_area_light) {
          warn(s.loc, "area lights inside object instances are not supported (as in pbrt-v4); the shape does not emit");
        } else {
          const TransformedEntity& a = desc_.area_lights.at(s.area_light);
          if (const char* why = prim.shape->emitter_refusal())
            throw_error(s.loc, fmt::format("Shape \"{}\" cannot be an area light: {}", s.name, why));
          if (const char* caveat = prim.shape->emitter_caveat())
            warn(s.loc, fmt::format("Shape \"{}\" as an area light: {}", s.name, caveat));
          AreaLightContext actx{a.params, *prim.shape, s.reverse_orientation, *setup_.textures, desc_.search_dir};
          auto light = reg_.area_lights.at(a.name, a.loc)(actx);
          prim.area_light = light.get();
          light_sources_.emplace_back(light.get(), &a);
          setup_.scene->add_light(std::move(light));
        }
      }
      prims.push_back(std::move(prim));
    }
    return prims;
  }

  // A render makes a material when a shape first uses it; a check makes them all, as pbrt-v4
  // does, so that one no shape uses (or whose shapes are in a missing file) is checked too.
  void check_every_material() {
    for (size_t i = 1; i < desc_.materials.size(); ++i)  // 0: the implicit default
      attempt([&] { material(MaterialRef{int(i), ""}, desc_.materials[i].loc); });
    for (const auto& [name, e] : desc_.named_materials) attempt([&] { material(MaterialRef{-1, name}, e.loc); });
  }

  // With keep_going the material is made first on its own, so that its errors are reported
  // even when the shape's own (a missing mesh) stop the shape.
  void check_material_first(const ShapeEntity& s) {
    if (keep_going_) attempt([&] { material(s.material, s.loc); });
  }

  void add_shape(const ShapeEntity& s) {
    check_material_first(s);
    if (s.animated) {
      // The parser refused an area light on a moving shape (pbrt-v4 does too).
      setup_.scene->add_moving_primitives(make_primitives(s, false, Transform()),
                                          motion(s.world_from_object, s.world_from_object_end));
      return;
    }
    for (auto& prim : make_primitives(s, true, s.world_from_object)) setup_.scene->add_primitive(std::move(prim));
  }

  // The object's still shapes make its instance; each moving one is built once in its object
  // space and placed at every use of the object (Embree instances one level deep: a moving
  // shape, itself an instance, cannot sit inside the object's).
  // Every shape of the object is tried and its errors collected (a missing mesh does not hide
  // the next one's); the object is defined only when all of them built. False when it is not.
  bool build_instance(const InstanceDefinition& def) {
    std::vector<Primitive> prims;
    bool built = true;
    for (const ShapeEntity& s : def.shapes)
      built = attempt([&] {
                check_material_first(s);
                if (s.animated) {
                  int group = setup_.scene->define_moving_group(make_primitives(s, false, Transform()));
                  if (group >= 0) moving_members_[def.name].push_back({group, &s});
                  return;
                }
                for (auto& prim : make_primitives(s, false, s.world_from_object)) prims.push_back(std::move(prim));
              }) &&
              built;
    return built && attempt([&] { setup_.scene->define_instance(def.name, std::move(prims)); });
  }

  // A moving shape of the object at one use: the use's transform times the shape's, keyframe by
  // keyframe. pbrt-v4 applies the use's transform to the shape's interpolated one; the two agree
  // when the use is still and a rotation with a uniform scale. Under a moving use pbrt-v4
  // multiplies two interpolations, which two keyframes cannot hold: said in a warning.
  void place_moving_members(const InstanceUse& u) {
    auto it = moving_members_.find(u.name);
    if (it == moving_members_.end()) return;
    if (u.animated())
      warn(u.loc, fmt::format("ObjectInstance \"{}\" moves and so do shapes inside it: their motions are combined "
                              "keyframe by keyframe (start with start, end with end), which differs from pbrt-v4's "
                              "product of the two motions in between",
                              u.name));
    for (const MovingMember& m : it->second) {
      try {
        setup_.scene->place_moving_group(m.group, motion(*u.world_from_instance * m.shape->world_from_object,
                                                         u.end_transform() * m.shape->world_from_object_end));
      } catch (const std::domain_error& e) {
        fail(u.loc, "ObjectInstance \"{}\": its shape at {} cannot move with it: {}", u.name, m.shape->loc.to_string(),
             e.what());
      }
    }
  }

  // A light whose power overflows float would never be chosen by the light sampler, and its
  // radiance would turn every sample it lights into a discarded one: refuse it instead.
  // Runs after commit(): distant and infinite lights know their power once the scene's size is.
  void check_light_power() const {
    for (const auto& [light, e] : light_sources_) {
      if (std::isfinite(light->power())) continue;
      std::string culprit = "scale";
      for (const char* name : {"scale", "power", "illuminance", "L", "I", "filename"})
        if (e->params.has(name)) {
          culprit = name;
          break;
        }
      e->params.fail(culprit,
                     "the light's power overflows the float range (its emission times \"scale\" times its "
                     "size, or the scene's for a distant or infinite light, is above 3.4e38)");
    }
  }

  const SceneDescription& desc_;
  RenderSetup& setup_;
  const bool keep_going_;
  const Registry& reg_ = Registry::builtin();
  std::map<std::string, const Material*> materials_;
  std::map<std::string, const Medium*> media_;   // null: vacuum (an unsupported type)
  std::set<std::string> materials_in_progress_;  // being made (a mix naming materials)
  std::set<const Material*> interfaces_;         // the "interface" materials made
  std::vector<std::pair<const Light*, const SceneEntity*>> light_sources_;
  struct MovingMember {
    int group;  // Scene::define_moving_group's
    const ShapeEntity* shape;
  };
  std::map<std::string, std::vector<MovingMember>> moving_members_;  // by object name
  DiagnosticList errors_;
};

// The camera's place over the TransformTimes (still: its one transform).
static AnimatedTransform camera_motion(const SceneDescription& desc) {
  if (!desc.camera.animated) return AnimatedTransform(desc.camera.world_from_camera);
  return AnimatedTransform(desc.camera.world_from_camera, desc.camera.transform_start_time,
                           desc.camera.world_from_camera_end, desc.camera.transform_end_time);
}

std::unique_ptr<Camera> make_camera(const SceneDescription& desc, const RenderOverrides& o, IVec2 resolution) {
  const Registry& reg = Registry::builtin();
  const SceneEntity& cam = scene_camera(desc, o);
  CameraContext ctx{cam.params, desc.camera.world_from_camera, resolution, desc.search_dir};
  if (desc.camera.animated) ctx.world_from_camera_motion = camera_motion(desc);
  auto camera = reg.cameras.at(cam.name, cam.loc)(ctx);
  return camera;
}

void check_memory(const FilmSettings& f, const RenderOverrides& o) {
  // The film holds 4 doubles per pixel and the output image 3 floats, a spectral film one
  // double and one float more per bucket, a gbuffer film 24 doubles and 20 floats more.
  uint64_t bytes =
      uint64_t(f.bounds.area()) * (32 + 12 + 12 * uint64_t(f.buckets.count) +
                                   (f.gbuffer ? 8 * GBuffer::kAccumulators + 4 * uint64_t(GBuffer::kChannels) : 0));
  if (o.max_memory_bytes && bytes > o.max_memory_bytes)
    throw_error(fmt::format("a {}x{} film needs about {:.1f} GiB, more than the limit of {:.1f} GiB (--max-memory)",
                            f.bounds.width(), f.bounds.height(), bytes / 1073741824.0,
                            o.max_memory_bytes / 1073741824.0));
}

// pbrt-v4 Options: "seed" seeds the sampler (unless --seed is given); the others change
// things eyetrace does not have, and are named in a warning rather than dropped silently.
std::optional<uint64_t> apply_options(const SceneDescription& desc) {
  std::optional<uint64_t> seed;
  for (const SceneEntity& o : desc.options) {
    if (o.name == "seed") {
      int v = o.params.get_int("seed", 0);
      if (v < 0) o.params.fail("seed", "must not be negative");
      seed = uint64_t(v);
    } else {
      o.params.mark_all_used();
      warn(o.loc, fmt::format("Option \"{}\" is not supported by eyetrace; ignored", o.name));
    }
  }
  if (desc.color_space != "srgb")
    warn(SourceLoc{},
         fmt::format("ColorSpace \"{}\": eyetrace renders in linear sRGB primaries; RGB values are used as given",
                     desc.color_space));
  return seed;
}

}  // namespace

std::unique_ptr<Camera> build_camera(const SceneDescription& desc, const RenderOverrides& o) {
  FilmSettings f = read_film(desc.film, scene_camera(desc, o), o);
  return make_camera(desc, o, f.resolution);
}

// Each plugin is tried and its errors collected, so a scene with several mistakes reports them
// all; only the film comes first alone, since every other part depends on its size.
RenderSetup build_render_setup(const SceneDescription& desc, const RenderOverrides& o) {
  const Registry& reg = Registry::builtin();
  RenderSetup setup;
  SceneFileLog files;
  DiagnosticList errors;
  auto attempt = [&errors](auto&& f) {
    try {
      f();
      return true;
    } catch (const SceneError& e) {
      errors.add_all(e.diagnostics());
      return false;
    }
  };
  FilmSettings f;
  if (!attempt([&] { f = read_film(desc.film, scene_camera(desc, o), o); })) {
    if (!o.keep_going) errors.throw_if_any();
    f.bounds = crop_to_pixels(f.resolution, Vec4(0.f, 1.f, 0.f, 1.f));
  }
  check_memory(f, o);
  setup.output_filename = f.filename;
  attempt([&] { setup.camera = make_camera(desc, o, f.resolution); });
  uint64_t render_seed = 0;
  attempt([&] {
    const SceneEntity& s = desc.sampler;
    std::optional<uint64_t> option_seed = apply_options(desc);
    render_seed = o.seed.value_or(option_seed.value_or(0));
    SamplerContext sctx{s.params, f.resolution, o.spp, render_seed};
    setup.sampler = reg.samplers.at(s.name, s.loc)(sctx);
  });
  attempt([&] {
    const SceneEntity& pf = desc.filter;
    auto filter = reg.filters.at(pf.name, pf.loc)(pf.params);
    setup.film = std::make_unique<Film>(f.resolution, f.bounds, std::move(filter), f.scale, f.buckets, f.response);
    // pbrt-v4's "camera" space is the camera's own at each sample's time (its CameraTransform's
    // RenderFromCamera, inverted).
    if (f.gbuffer) setup.film->enable_gbuffer(f.gbuffer_world ? AnimatedTransform() : camera_motion(desc));
  });
  // The integrator looks at the built scene's lights: it is made only when the scene was.
  const SceneEntity& in = desc.integrator;
  if (attempt([&] { Builder(desc, setup, o.keep_going).build_world(); }))
    attempt([&] {
      IntegratorContext ictx{in.params, *setup.scene, render_seed};
      setup.integrator = reg.integrators.at(in.name, in.loc)(ictx);
      // As pbrt-v4 warns: only volpath traces media (bdpt hands such scenes to volpath and says so).
      if (setup.scene->has_media() && in.name != "volpath" && in.name != "bdpt")
        warn(in.loc, fmt::format("integrator \"{}\" ignores participating media; \"volpath\" traces them", in.name));
    });
  else if (o.keep_going)  // no scene to make it for: its name and parameters are still checked
    attempt([&] {
      reg.integrators.at(in.name, in.loc);
      PluginParams(in.params, *reg.integrators.find(in.name)->spec, in.name);
    });
  errors.throw_if_any();
  setup.description = fmt::format("{}\n{}\n{}\n{}", setup.camera->to_string(), setup.sampler->to_string(),
                                  setup.film->filter().to_string(), setup.integrator->to_string());
  setup.files_read = files.files();
  return setup;
}

}  // namespace eyetrace
