// A render's resumable state, saved next to the output image as "<output>.state": the film's
// exact double accumulators (RGB, weight and, for a spectral film, one per wavelength bucket), the samples each tile
// holds, and the fingerprint (scene/scene_fingerprint.h) of everything that decides the image, so `eyetrace render
// --resume` continues a stopped render to the same bits an uninterrupted one gives, and refuses a state made for
// another scene.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "render/film.h"
#include "render/tile_progress.h"

namespace eyetrace {

struct RenderState {
  // 5: the accumulators hold 11 + 3 buckets doubles per pixel: r, g, b, weight, the three splat
  // sums, the sum of squared luminances, the three share sums, the buckets, their splat sums and
  // their share sums; an adaptive render's per-pixel counts and targets follow the tile counts
  // (version 4: 8 + 2 buckets, no share sums; 3: no squared luminances, no adaptive renders; 2: no splat sums; 1: 4
  // accumulators, RGB films only).
  static constexpr uint32_t kVersion = 5;
  uint64_t fingerprint = 0;  // of the scene and every option that changes the image
  IVec2 resolution{0};
  PixelBounds bounds;
  int samples_per_pixel = 0;  // requested
  TileProgress tiles;
  int spectral_buckets = 0;          // Film::buckets().count (0: an RGB film)
  std::vector<double> accumulators;  // Film::accumulators()
  uint64_t nonfinite_samples = 0;
};

// The state file that belongs to an output image.
inline std::string state_path(const std::string& output) { return output + ".state"; }

// Writes through a temporary file and a rename, like images. Throws SceneError naming the file.
void write_render_state(const std::string& path, const RenderState& state);
// Throws SceneError naming the file when it is missing, truncated, corrupt or another version.
RenderState read_render_state(const std::string& path);

}  // namespace eyetrace
