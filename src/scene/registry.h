// The one registration list. Every built-in plugin is a name, a kind and a factory; the
// list itself is register_builtin_plugins() in builtin_plugins.cpp, one line per plugin.
// Factories validate their parameters (ParameterList lookups) and report leftovers.
#pragma once
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/camera.h"
#include "core/filter.h"
#include "core/light.h"
#include "core/material.h"
#include "core/sampler.h"
#include "core/shape.h"
#include "core/texture.h"
#include "core/transform.h"
#include "scene/params.h"

namespace eyetrace {

class Integrator;
class Scene;
class TextureStore;
class ImageTextureCache;

// Film geometry a camera needs: the full resolution (crop windows do not change projection).
struct CameraContext {
  const ParameterList& params;
  Transform world_from_camera;
  IVec2 resolution;
  std::string search_dir;
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
};

// Resolves material/texture parameters that may be a constant or a named texture.
struct MaterialContext {
  const ParameterList& params;
  TextureStore& textures;
  std::string search_dir;
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

struct IntegratorContext {
  const ParameterList& params;
  const Scene& scene;
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
using IntegratorFactory = std::function<std::unique_ptr<Integrator>(const IntegratorContext&)>;

struct Registry {
  std::map<std::string, CameraFactory> cameras;
  std::map<std::string, SamplerFactory> samplers;
  std::map<std::string, ShapeFactory> shapes;
  std::map<std::string, MaterialFactory> materials;
  std::map<std::string, FloatTextureFactory> float_textures;
  std::map<std::string, SpectrumTextureFactory> spectrum_textures;
  std::map<std::string, LightFactory> lights;
  std::map<std::string, AreaLightFactory> area_lights;
  std::map<std::string, FilterFactory> filters;
  std::map<std::string, IntegratorFactory> integrators;

  // The registry of built-in plugins, made once on first use.
  static const Registry& builtin();
};

void register_builtin_plugins(Registry& r);

// Looks `name` up in `table`; unknown names are errors at `loc` that list the known ones.
template <typename Map>
const typename Map::mapped_type& find_plugin(const Map& table, const std::string& kind, const std::string& name,
                                             const SourceLoc& loc) {
  auto it = table.find(name);
  if (it != table.end()) return it->second;
  std::vector<std::string> names;
  std::string list;
  for (const auto& [n, f] : table) {
    names.push_back(n);
    list += (list.empty() ? "" : ", ") + n;
  }
  std::string hint = closest_match(name, names);
  fail(loc, "unsupported {} \"{}\"{}; eyetrace supports: {}", kind, name,
       hint.empty() ? "" : fmt::format(" (did you mean \"{}\"?)", hint), list);
}

}  // namespace eyetrace
