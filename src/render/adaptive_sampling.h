// Adaptive sampling (`render --adaptive`): every pixel takes `min_spp` samples; then, in passes,
// each pixel gets samples in proportion to how noisy its samples are, which is what makes the
// image's error smallest for the samples spent, up to `max_spp`.
//
// The relative error of pixel p's mean after n_p samples is e_p = sigma_p / sqrt(n_p), with
//   sigma_p = sqrt(n_p Var[mean_p] / (mean_p^2 + floor^2)),
// the relative standard deviation of one sample: Var[mean_p] estimated from the pixel's own
// samples (the sums of w Y and (w Y)^2 the film keeps, Film::Moments), floor = kFloorFraction
// times the image's mean luminance so that near-black pixels, whose relative error nobody sees,
// do not take every sample. The image's mean squared relative error, mean(sigma_p^2 / n_p), is
// smallest for a given number of samples when n_p is proportional to sigma_p (a Lagrange
// multiplier), so the target E, the RMS of the pixels' relative errors, is met with
//   n_p = k sigma_p,  k = mean(sigma) / E^2.
// (Stopping each pixel when its own e_p reaches E gives n_p proportional to sigma_p^2 and exactly
// the error a uniform render has with as many samples: no gain. docs/adaptive-sampling.md.)
// Three things keep a pixel whose few samples happen to agree from getting too few: no pixel is
// judged before min_spp samples; a pixel's sigma is the larger of its own and the mean over its
// 3x3 neighbourhood (a lucky pixel beside noisy ones goes on: noise is spatially smooth in scale,
// luck is not; the maximum instead would spread the noise of every edge to its neighbours, and
// measured, gives up most of the gain); and every pass re-estimates sigma and k from all samples
// so far, so a pixel can take more later.
//
// Bias: how many samples a pixel gets depends on the samples taken, so its mean is not exactly
// unbiased (a pixel whose first samples happened to be alike gets fewer). The measured effect is
// in docs/adaptive-sampling.md.
//
// Reproducibility: pass sizes depend only on the options and estimates (no clock); decisions
// use the film as it is at a pass end, and every pixel sums its samples in index order, so the
// same seed gives the same image for any thread count or number of processes and however the
// render is interrupted and resumed (the per-pixel counts and targets are in the render state).
#pragma once
#include <vector>

#include "render/film.h"
#include "render/tile_progress.h"

namespace eyetrace {

struct AdaptiveOptions {
  double target_error = 0;  // the RMS over pixels of their mean luminance's relative error
  int min_spp = 16;         // samples every pixel takes before any is judged; the smallest pass
  int max_spp = 0;          // the cap: the sampler's samples per pixel
  static constexpr double kFloorFraction = 0.1;
};

// Sets `tiles` up for an adaptive render of `bounds`: every pixel's first pass ends at min_spp.
void start_adaptive(const PixelBounds& bounds, const AdaptiveOptions& opts, TileProgress& tiles);

// The most samples a pixel may hold after the pass that follows one whose largest target was
// `end`: twice as many, at least min_spp more, at most max_spp (so that sigma is re-estimated
// before a pixel's count grows much).
int next_pass_end(int end, const AdaptiveOptions& opts);

// Each pixel's relative error e_p (see above), row-major over the film's bounds, from the film
// and the samples each pixel holds (tiles.pixel_done). A pixel with fewer than 2 samples gets +inf.
std::vector<double> pixel_errors(const Film& film, const TileProgress& tiles);

// The samples each pixel should have in all: k times its pooled sigma, rounded to a power of
// two, within [min_spp, max_spp] (row-major).
std::vector<int> wanted_samples(const Film& film, const AdaptiveOptions& opts, const TileProgress& tiles);

// After a pass every pixel finished: each pixel that has fewer samples than it wants gets, as
// its target, what it wants but at most the next pass's end; the others keep what they have.
// Returns how many pixels go on (0: the render is complete).
size_t plan_next_pass(const Film& film, const AdaptiveOptions& opts, TileProgress& tiles);

}  // namespace eyetrace
