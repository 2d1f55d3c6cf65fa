#include "render/adaptive_sampling.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace eyetrace {

void start_adaptive(const PixelBounds& bounds, const AdaptiveOptions& opts, TileProgress& tiles) {
  tiles = TileProgress::start(bounds);
  tiles.pixel_done.assign(bounds.area(), 0);
  tiles.pixel_target.assign(bounds.area(), std::min(opts.min_spp, opts.max_spp));
}

int next_pass_end(int end, const AdaptiveOptions& opts) {
  const long grown = long(end) + std::max(long(opts.min_spp), long(end));
  return int(std::min(grown, long(opts.max_spp)));
}

std::vector<double> pixel_errors(const Film& film, const TileProgress& tiles) {
  const PixelBounds& b = film.bounds();
  const size_t area = b.area();
  std::vector<double> mean(area, 0.0), var(area, 0.0);
  double image_mean = 0.0;
  for (size_t i = 0; i < area; ++i) {
    const IVec2 p = b.lo + IVec2(int(i % size_t(b.width())), int(i / size_t(b.width())));
    const Film::Moments m = film.moments(p);
    const double n = tiles.pixel_done[i];
    if (n < 2 || m.weight == 0.0) {
      var[i] = std::numeric_limits<double>::infinity();
      continue;
    }
    mean[i] = m.sum_y / m.weight;
    // The sample variance of w Y (clamped: rounding can make it a hair negative when all agree),
    // and the ratio estimator's variance Var[sum wY / sum w] ~ n s^2 / (sum w)^2.
    const double s2 = std::max(0.0, (m.sum_y2 - m.sum_y * m.sum_y / n) / (n - 1.0));
    var[i] = n * s2 / (m.weight * m.weight);
    image_mean += mean[i];
  }
  image_mean /= double(area);
  const double floor2 = std::pow(AdaptiveOptions::kFloorFraction * image_mean, 2);
  std::vector<double> e(area);
  for (size_t i = 0; i < area; ++i) {
    const double d = mean[i] * mean[i] + floor2;
    // A black image (floor 0) with a black pixel: no error to speak of unless it varies.
    e[i] = d > 0.0 ? std::sqrt(var[i] / d) : (var[i] > 0.0 ? std::numeric_limits<double>::infinity() : 0.0);
  }
  return e;
}

std::vector<int> wanted_samples(const Film& film, const AdaptiveOptions& opts, const TileProgress& tiles) {
  const std::vector<double> e = pixel_errors(film, tiles);
  const PixelBounds& b = film.bounds();
  const int w = b.width(), h = b.height();
  std::vector<double> sigma(e.size());
  for (size_t i = 0; i < e.size(); ++i) sigma[i] = e[i] * std::sqrt(double(tiles.pixel_done[i]));
  std::vector<double> pooled(e.size(), 0.0);
  double mean = 0.0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double& p = pooled[size_t(y) * size_t(w) + size_t(x)];
      double sum = 0.0;
      int count = 0;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int xx = x + dx, yy = y + dy;
          if (xx >= 0 && yy >= 0 && xx < w && yy < h) {
            sum += sigma[size_t(yy) * size_t(w) + size_t(xx)];
            ++count;
          }
        }
      p = std::max(sigma[size_t(y) * size_t(w) + size_t(x)], sum / count);
      mean += std::min(p, 1e30) / double(e.size());  // an unjudged (+inf) pixel must not make k infinite
    }
  const double k = mean / (opts.target_error * opts.target_error);
  std::vector<int> wanted(e.size());
  for (size_t i = 0; i < e.size(); ++i) {
    // k is finite and pooled >= 0 (possibly +inf, but then k > 0): n is never NaN (log2(0) is
    // -inf, exp2 of it 0); still, only a number below the cap is converted.
    const double n = std::exp2(std::round(std::log2(k * pooled[i])));
    wanted[i] = n < double(opts.max_spp) ? std::max(opts.min_spp, int(n)) : opts.max_spp;
  }
  return wanted;
}

size_t plan_next_pass(const Film& film, const AdaptiveOptions& opts, TileProgress& tiles) {
  const std::vector<int> wanted = wanted_samples(film, opts, tiles);
  const int end = *std::max_element(tiles.pixel_target.begin(), tiles.pixel_target.end());
  const int next = next_pass_end(end, opts);
  size_t going_on = 0;
  for (size_t i = 0; i < wanted.size(); ++i)
    if (tiles.pixel_done[i] < wanted[i]) {
      tiles.pixel_target[i] = std::min(wanted[i], next);
      ++going_on;
    }
  return going_on;
}

}  // namespace eyetrace
