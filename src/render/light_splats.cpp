#include "render/light_splats.h"

#include <algorithm>

#include "render/film.h"

namespace eyetrace {

LightSplatter::LightSplatter(const Film& film) {
  const double integral = film.filter().integral();
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
