// The one registration list. Every built-in plugin is a name, a kind, a factory and its
// declared parameters (PluginSpec); the list itself is register_builtin_plugins() in
// builtin_plugins.cpp, one line per plugin. Factories check their parameters against their
// spec (PluginParams) before reading them.
#pragma once
#include <algorithm>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/animated_transform.h"
#include "core/camera.h"
#include "core/filter.h"
#include "core/light.h"
#include "core/material.h"
#include "core/medium.h"
#include "core/sampler.h"
#include "core/shape.h"
#include "core/texture.h"
#include "core/transform.h"
#include "scene/param_spec.h"
#include "scene/params.h"

namespace eyetrace {

class Integrator;
class Scene;
class TextureStore;
class ImageTextureCache;

// Film geometry a camera needs: the full resolution (crop windows do not change projection).
struct CameraContext {
  const ParameterList& params;
  Transform world_from_camera;  // at the start time
  IVec2 resolution;
  std::string search_dir;
  // The camera's motion over the TransformTimes (not animated when it stands still).
  AnimatedTransform world_from_camera_motion = {};
};

struct SamplerContext {
  const ParameterList& params;
  IVec2 resolution;
  int spp_override = 0;  // > 0: --spp from the command line replaces "pixelsamples"
  uint64_t seed = 0;     // --seed (or the "seed" parameter)
};

struct ShapeContext {
  const ParameterList& params;
  Transform world_from_object;
  bool reverse_orientation = false;
  std::string search_dir;
  // For "texture alpha" (named float textures); null where there are none (tests).
  TextureStore* textures = nullptr;
};

// Resolves material/texture parameters that may be a constant or a named texture.
struct MaterialContext {
  const ParameterList& params;
  TextureStore& textures;
  std::string search_dir;
  // The material MakeNamedMaterial defined under a name (made on first use; null for an
  // "interface"); throws SceneError for an unknown name or a material that would contain
  // itself. Unset where no named materials exist (tests).
  std::function<const Material*(const std::string& name)> named_material = {};
};

struct TextureContext {
  const ParameterList& params;
  Transform world_from_texture;
  TextureStore& textures;  // earlier textures (for scale/mix) and the image cache
  std::string search_dir;
};

struct LightContext {
  const ParameterList& params;
  Transform world_from_light;
  std::string search_dir;
};

struct AreaLightContext {
  const ParameterList& params;
  const Shape& shape;
  bool reverse_orientation = false;
  TextureStore& textures;
  std::string search_dir;
};

// A medium's parameters and the transform current at its MakeNamedMedium (grids are placed by it).
struct MediumContext {
  const ParameterList& params;
  Transform world_from_medium;
  std::string search_dir;  // where files the medium names are looked for (nanovdb)
};

struct IntegratorContext {
  const ParameterList& params;
  const Scene& scene;
  uint64_t seed = 0;  // the render's seed (--seed or Option "seed"): pbrt-v4's default for sppm's "seed"
};

using CameraFactory = std::function<std::unique_ptr<Camera>(const CameraContext&)>;
using SamplerFactory = std::function<std::unique_ptr<Sampler>(const SamplerContext&)>;
using ShapeFactory = std::function<std::vector<std::unique_ptr<Shape>>(const ShapeContext&)>;
using MaterialFactory = std::function<std::unique_ptr<Material>(const MaterialContext&)>;
using FloatTextureFactory = std::function<std::unique_ptr<FloatTexture>(const TextureContext&)>;
using SpectrumTextureFactory = std::function<std::unique_ptr<SpectrumTexture>(const TextureContext&)>;
using LightFactory = std::function<std::unique_ptr<Light>(const LightContext&)>;
using AreaLightFactory = std::function<std::unique_ptr<Light>(const AreaLightContext&)>;
using FilterFactory = std::function<std::unique_ptr<Filter>(const ParameterList&)>;
using MediumFactory = std::function<std::unique_ptr<Medium>(const MediumContext&)>;
using IntegratorFactory = std::function<std::unique_ptr<Integrator>(const IntegratorContext&)>;

// One kind of plugin: name -> factory and declared parameters, in registration order.
template <typename Factory>
struct PluginTable {
  struct Entry {
    std::string name;
    Factory create;
    const PluginSpec* spec;
  };
  std::string kind;  // "camera", "float texture", ... (for messages and listings)
  std::vector<Entry> entries;

  void add(std::string name, Factory create, const PluginSpec& spec) {
    entries.push_back(Entry{std::move(name), std::move(create), &spec});
  }
  const Entry* find(const std::string& name) const {
    for (const Entry& e : entries)
      if (e.name == name) return &e;
    return nullptr;
  }
  // The factory of `name`; unknown names are errors at `loc` that list the known ones.
  const Factory& at(const std::string& name, const SourceLoc& loc) const {
    if (const Entry* e = find(name)) return e->create;
    std::vector<std::string> names;
    for (const Entry& e : entries) names.push_back(e.name);
    std::sort(names.begin(), names.end());
    std::string list;
    for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
    std::string hint = closest_match(name, names);
    fail(loc, "unsupported {} \"{}\"{}; eyetrace supports: {}", kind, name,
         hint.empty() ? "" : fmt::format(" (did you mean \"{}\"?)", hint), list);
  }
};

// A listed plugin: what `eyetrace plugins` and the generated docs show.
struct PluginListing {
  std::string kind;
  std::string name;
  const PluginSpec* spec;
};

struct Registry {
  PluginTable<CameraFactory> cameras{"camera"};
  PluginTable<SamplerFactory> samplers{"sampler"};
  PluginTable<FilterFactory> filters{"pixel filter"};
  PluginTable<ShapeFactory> shapes{"shape"};
  PluginTable<MaterialFactory> materials{"material"};
  PluginTable<FloatTextureFactory> float_textures{"float texture"};
  PluginTable<SpectrumTextureFactory> spectrum_textures{"spectrum texture"};
  PluginTable<LightFactory> lights{"light"};
  PluginTable<AreaLightFactory> area_lights{"area light"};
  PluginTable<MediumFactory> media{"medium"};
  PluginTable<IntegratorFactory> integrators{"integrator"};
  // Directives that are built in rather than plugins but declare their parameters too (Film).
  std::vector<PluginListing> built_in;

  // Every plugin, kind by kind in the order above, each kind in registration order.
  std::vector<PluginListing> listing() const;

  // The registry of built-in plugins, made once on first use.
  static const Registry& builtin();
};

void register_builtin_plugins(Registry& r);

}  // namespace eyetrace
