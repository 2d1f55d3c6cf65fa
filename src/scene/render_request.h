// What a render asks of a scene beyond its text: the overrides of `eyetrace render` (--camera,
// --resolution, --crop, --spp, --seed, --max-memory, --output), read and checked in one place,
// and the render setup built from a scene with them. The command line and the Python module's
// render() both go through here, so a scene renders the same from either.
#pragma once
#include <cstdint>
#include <string>

#include "core/math.h"
#include "scene/scene_builder.h"
#include "scene/scene_description.h"

namespace eyetrace {

struct RenderRequest {
  std::string camera;         // a Camera directive replacing the scene's ("" keeps it)
  std::string resolution;     // "WxH" ("" keeps the Film's)
  std::string crop;           // "x0,x1,y0,y1" fractions ("" keeps the Film's cropwindow)
  int spp = 0;                // samples per pixel (0 keeps the Sampler's)
  int64_t seed = -1;          // sampler seed (< 0 keeps the Sampler's)
  double max_memory_gib = 0;  // refuse renders predicted to need more (0: 3/4 of the RAM)
  std::string output;         // replaces the Film's filename ("" keeps it)
};

// "WxH" with 1 <= W, H <= 32768; a SceneError naming --resolution otherwise.
IVec2 parse_resolution(const std::string& text);
// "x0,x1,y0,y1" with 0 <= x0 < x1 <= 1 and 0 <= y0 < y1 <= 1; a SceneError naming --crop otherwise.
Vec4 parse_crop(const std::string& text);

// The request as the scene builder's overrides (each field checked; errors name the option).
RenderOverrides render_overrides(const RenderRequest& request);

// The scene with the request's overrides, ready to render.
RenderSetup build_requested_setup(const SceneDescription& scene, const RenderRequest& request);

}  // namespace eyetrace
