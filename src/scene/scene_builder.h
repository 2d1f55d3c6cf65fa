// Turns a parsed SceneDescription (plus command-line overrides) into everything a render
// needs, creating each plugin through the registry and reporting unused parameters.
#pragma once
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "core/camera.h"
#include "core/sampler.h"
#include "render/film.h"
#include "render/integrator.h"
#include "render/scene.h"
#include "scene/param_spec.h"
#include "scene/scene_description.h"
#include "scene/texture_store.h"

namespace eyetrace {

struct RenderOverrides {
  std::optional<SceneEntity> camera;  // --camera: replaces name and parameters, keeps the transform
  std::optional<IVec2> resolution;    // --resolution
  int spp = 0;                        // --spp
  std::optional<uint64_t> seed;       // --seed
  std::optional<Vec4> crop;           // --crop
  uint64_t max_memory_bytes = 0;      // refuse scenes predicted to need more (0: no limit)
  std::string output;                 // --output, replacing the Film's filename ("" when not given)
  // `eyetrace check`: build as far as possible to find every error. A film that fails is
  // replaced by the default one and a texture that fails by a constant stand-in, so that the
  // shapes and materials after them are still built and checked; the errors are thrown at the end.
  bool keep_going = false;
};

struct RenderSetup {
  std::unique_ptr<TextureStore> textures;  // outlives materials that point into it
  std::unique_ptr<Scene> scene;
  std::unique_ptr<Camera> camera;
  std::unique_ptr<Sampler> sampler;
  std::unique_ptr<Film> film;
  std::unique_ptr<Integrator> integrator;
  std::string output_filename;          // the Film's "filename" (the command line may override it)
  std::string description;              // one line per plugin, for --verbose and logs
  std::vector<std::string> files_read;  // every file the plugins read (scene/scene_files.h), sorted
};

// The Film directive's parameters (Film is built in, not a plugin): "rgb" (and "gbuffer",
// rendered as rgb) and "spectral" (the same plus its wavelength buckets).
const PluginSpec& film_spec();
const PluginSpec& spectral_film_spec();
const PluginSpec& gbuffer_film_spec();

RenderSetup build_render_setup(const SceneDescription& desc, const RenderOverrides& overrides);

// Only the camera (for `eyetrace optics` and tests): the Camera directive of `desc` with overrides.
std::unique_ptr<Camera> build_camera(const SceneDescription& desc, const RenderOverrides& overrides);

}  // namespace eyetrace
