#include "render/light_splats.h"

#include <algorithm>

#include "render/film.h"

namespace eyetrace {

namespace {

// The filter's integral by the midpoint rule on a 256 x 256 grid over its support: exact for
// the box and triangle filters (constant or linear on every cell), within 1e-4 for the smooth
// ones; computed here because Filter does not state it.
double filter_integral(const Filter& f) {
  constexpr int n = 256;
  const Vec2 r = f.radius();
  double sum = 0;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x)
      sum += f.evaluate(Vec2(-r.x + (x + 0.5f) * 2.f * r.x / n, -r.y + (y + 0.5f) * 2.f * r.y / n));
  return sum * (4.0 * double(r.x) * double(r.y)) / (double(n) * n);
}

}  // namespace

LightSplatter::LightSplatter(const Film& film) {
  const double integral = filter_integral(film.filter());
  const double pixels = double(film.resolution().x) * double(film.resolution().y);
  const double area = double(film.bounds().area());
  scale_ = integral != 0 && area > 0 ? float(pixels / area / integral) : 0.f;
}

void LightSplatter::add(Film& film, const LightSplat& s) const {
  // pbrt-v4's RGBFilm::AddSplat: every pixel whose filter reaches the point.
  const Vec2 r = film.filter().radius();
  const Vec2 p = s.p_raster + Vec2(0.5f);
  const PixelBounds& b = film.bounds();
  const IVec2 lo = glm::max(IVec2(glm::floor(p - r)), b.lo);
  const IVec2 hi = glm::min(IVec2(glm::floor(p + r)) + IVec2(1), b.hi);
  for (int y = lo.y; y < hi.y; ++y)
    for (int x = lo.x; x < hi.x; ++x) {
      const float w = film.filter().evaluate(s.p_raster - Vec2(float(x) + 0.5f, float(y) + 0.5f));
      if (w != 0.f) film.add_splat(IVec2(x, y), s.L * (w * scale_), s.lambda);
    }
}

void LightSplatter::flush(Film& film, std::vector<LightSplats>& tiles, int first, int end) const {
  std::vector<size_t> cursor(tiles.size(), 0);
  for (int i = first; i < end; ++i)
    for (size_t t = 0; t < tiles.size(); ++t) {
      const std::vector<LightSplat>& list = tiles[t].list();
      size_t& c = cursor[t];
      while (c < list.size() && list[c].index == i) add(film, list[c++]);
    }
  for (LightSplats& t : tiles) t.clear();
}

}  // namespace eyetrace
