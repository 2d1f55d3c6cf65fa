// Adaptive sampling (`render --adaptive`): every pixel takes `min_spp` samples; then, in passes,
// only the pixels whose estimated error is still above the target take more, up to `max_spp`.
//
// The error of pixel p is the standard error of its mean luminance relative to that mean,
//   e_p = sqrt(Var[mean_p] / (mean_p^2 + floor^2)),
// Var[mean_p] estimated from the pixel's own samples (the sums of w Y and (w Y)^2 the film keeps,
// Film::Moments), floor = kFloorFraction times the image's mean luminance so that near-black
// pixels, whose relative error nobody sees, do not take every sample. Three things keep a pixel
// whose few samples happen to agree from stopping too early: no pixel is judged before min_spp
// samples; a pixel's error is the largest raw e over its 3x3 neighbourhood (a lucky pixel beside
// noisy ones goes on: noise is spatially smooth in scale, luck is not); and a pixel stops only
// once, at a pass end, so its mean is never re-weighted.
//
// Bias: the decision to stop depends on the samples taken, so the stopped mean is not exactly
// unbiased (a pixel whose samples happened to be low and alike stops a little more often). The
// measured effect is in docs/adaptive-sampling.md.
//
// Reproducibility: the passes end at sample counts that depend only on the options (1.5x
// growth); decisions use the film as it is at a pass end, and every pixel sums its samples in
// index order, so the same seed gives the same image for any thread count and however the render
// is interrupted and resumed (the per-pixel counts and targets are part of the render state).
#pragma once
#include <vector>

#include "render/film.h"
#include "render/tile_progress.h"

namespace eyetrace {

struct AdaptiveOptions {
  double target_error = 0;  // relative standard error of a pixel's mean luminance
  int min_spp = 16;         // samples every pixel takes before any is judged; the smallest pass
  int max_spp = 0;          // the cap: the sampler's samples per pixel
  static constexpr double kFloorFraction = 0.1;
};

// Sets `tiles` up for an adaptive render of `bounds`: every pixel's first pass ends at min_spp.
void start_adaptive(const PixelBounds& bounds, const AdaptiveOptions& opts, TileProgress& tiles);

// The end of the pass after one that ended at `end`: half as many samples again, at least
// min_spp more, at most max_spp.
int next_pass_end(int end, const AdaptiveOptions& opts);

// Each pixel's raw error e_p (see above), row-major over the film's bounds, from the film and
// the samples each pixel holds (tiles.pixel_done). A pixel with fewer than 2 samples gets +inf.
std::vector<double> pixel_errors(const Film& film, const TileProgress& tiles);

// After a pass every pixel finished: the pixels whose pooled error is above the target and that
// are below max_spp get the next pass's end as their target; the others keep what they have.
// Returns how many pixels go on (0: the render is complete).
size_t plan_next_pass(const Film& film, const AdaptiveOptions& opts, TileProgress& tiles);

}  // namespace eyetrace
