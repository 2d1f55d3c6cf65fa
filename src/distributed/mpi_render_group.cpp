#include "distributed/mpi_render_group.h"

#include <algorithm>
#include <cstdio>
#include <exception>
#include <stdexcept>

#include "render/film.h"
#include "render/image_io.h"
#include "render/tile_progress.h"

namespace eyetrace {

namespace {

// The values one tile contributes to share() and collect(): its count, then per pixel
// (row-major) the film's accumulators and, adaptive, the pixel's count and target. Counts are
// small integers, exact in a double.
void pack_tile(size_t t, const Film& film, const TileProgress& tp, std::vector<double>& out) {
  const PixelBounds& b = film.bounds();
  const size_t per = film.accumulators_per_pixel();
  out.push_back(tp.done[t]);
  const PixelBounds tb = tp.tile_bounds(t, b);
  for (int y = tb.lo.y; y < tb.hi.y; ++y)
    for (int x = tb.lo.x; x < tb.hi.x; ++x) {
      const size_t i = size_t(y - b.lo.y) * size_t(b.width()) + size_t(x - b.lo.x);
      out.resize(out.size() + per);
      film.copy_accumulators(i, out.data() + out.size() - per);
      if (tp.adaptive()) out.insert(out.end(), {double(tp.pixel_done[i]), double(tp.pixel_target[i])});
    }
}

const double* unpack_tile(size_t t, const double* in, Film& film, TileProgress& tp) {
  const PixelBounds& b = film.bounds();
  const size_t per = film.accumulators_per_pixel();
  tp.done[t] = int(*in++);
  const PixelBounds tb = tp.tile_bounds(t, b);
  for (int y = tb.lo.y; y < tb.hi.y; ++y)
    for (int x = tb.lo.x; x < tb.hi.x; ++x) {
      const size_t i = size_t(y - b.lo.y) * size_t(b.width()) + size_t(x - b.lo.x);
      film.set_accumulators(i, in);
      in += per;
      if (tp.adaptive()) {
        tp.pixel_done[i] = int(in[0]);
        tp.pixel_target[i] = int(in[1]);
        in += 2;
      }
    }
  return in;
}

}  // namespace

std::vector<double> MpiRenderGroup::own_tiles(const Film& film, const TileProgress& tp) const {
  std::vector<double> mine;
  const size_t tiles = tp.done.size(), per = film.accumulators_per_pixel() + (tp.adaptive() ? 2 : 0);
  size_t values = 0;
  for (size_t t = 0; t < tiles; ++t)
    if (owns_tile(t, tiles)) values += 1 + tp.tile_bounds(t, film.bounds()).area() * per;
  mine.reserve(values);
  for (size_t t = 0; t < tiles; ++t)
    if (owns_tile(t, tiles)) pack_tile(t, film, tp, mine);
  return mine;
}

void MpiRenderGroup::unpack_others(const std::vector<double>& all, const std::vector<int>& offsets, Film& film,
                                   TileProgress& tp) const {
  const size_t tiles = tp.done.size();
  for (int r = 0; r < size(); ++r) {
    if (r == rank()) continue;  // its own tiles are already in place
    const double* in = all.data() + offsets[size_t(r)];
    for (size_t t = 0; t < tiles; ++t)
      if (tile_owner(t, tiles) == r) in = unpack_tile(t, in, film, tp);
  }
}

void MpiRenderGroup::share(Film& film, TileProgress& tp) {
  std::vector<double> all;
  std::vector<int> offsets;
  world_->all_gather(own_tiles(film, tp), all, offsets);
  unpack_others(all, offsets, film, tp);
}

void MpiRenderGroup::collect(Film& film, TileProgress& tp) {
  // Rank 0 sends nothing (its tiles are in place); the others send theirs to it alone.
  const std::vector<double> mine = rank() == 0 ? std::vector<double>() : own_tiles(film, tp);
  std::vector<double> all;
  std::vector<int> offsets;
  world_->gather_to_root(mine, all, offsets);
  if (rank() == 0) unpack_others(all, offsets, film, tp);
}

Image MpiRenderGroup::collect_image(const Film& film, TileProgress& tp) {
  const PixelBounds& b = film.bounds();
  const size_t tiles = tp.done.size(), channels = 3 + size_t(film.buckets().count);
  std::vector<float> values;
  std::vector<int> done;
  if (rank() != 0) {
    size_t pixels = 0;
    for (size_t t = 0; t < tiles; ++t)
      if (owns_tile(t, tiles)) pixels += tp.tile_bounds(t, b).area();
    if (pixels * channels > size_t(INT32_MAX))
      throw std::runtime_error("MPI: a rank's share of the image is too large");
    values.resize(pixels * channels);
    float* out = values.data();
    for (size_t t = 0; t < tiles; ++t) {
      if (!owns_tile(t, tiles)) continue;
      done.push_back(tp.done[t]);
      const PixelBounds tb = tp.tile_bounds(t, b);
      for (int y = tb.lo.y; y < tb.hi.y; ++y)
        for (int x = tb.lo.x; x < tb.hi.x; ++x, out += channels) film.pixel_channels(IVec2(x, y), out);
    }
  }
  Image image = rank() == 0 ? film.blank_image() : Image{};
  if (rank() == 0)
    for (size_t t = 0; t < tiles; ++t)
      if (owns_tile(t, tiles)) film.fill_image(tp.tile_bounds(t, b), image);
  std::vector<float> all_values;
  std::vector<int> all_done, value_offsets, done_offsets;
  world_->gather_to_root(values, all_values, value_offsets);
  world_->gather_to_root(done, all_done, done_offsets);
  if (rank() != 0) return image;
  for (int r = 1; r < size(); ++r) {
    const float* in = all_values.data() + value_offsets[size_t(r)];
    const int* count = all_done.data() + done_offsets[size_t(r)];
    for (size_t t = 0; t < tiles; ++t) {
      if (tile_owner(t, tiles) != r) continue;
      tp.done[t] = *count++;
      const PixelBounds tb = tp.tile_bounds(t, b);
      for (int y = tb.lo.y; y < tb.hi.y; ++y, in += size_t(tb.width()) * channels)
        std::copy(in, in + size_t(tb.width()) * channels, &image.at(tb.lo.x - b.lo.x, y - b.lo.y, 0));
    }
  }
  return image;
}

}  // namespace eyetrace
