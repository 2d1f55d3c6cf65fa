// Which pixels of a tile draw their film point uniformly when a dispersive eye splats with a
// smooth filter (core/splatting_camera.h): those whose filter's square of support stays inside
// the tile, checked here against that geometric statement itself.
#include <gtest/gtest.h>

#include "../support/unity_id.h"
#include "core/splatting_camera.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

TEST(SplattingCamera, UniformPixelsAreThoseWhoseFilterStaysInTheTile) {
  const IVec2 lo(32, 16), hi(48, 27);  // a tile at the image's bottom edge: 16 x 11 pixels
  for (float r : {0.25f, 0.5f, 0.75f, 1.0f, 1.2f, 1.5f, 2.0f, 2.5f, 3.5f}) {
    int uniform = 0;
    for (int y = lo.y; y < hi.y; ++y)
      for (int x = lo.x; x < hi.x; ++x) {
        // The support [x + 0.5 - r, x + 0.5 + r] x [...] within [lo, hi] along both axes.
        const bool inside = x + 0.5 - r >= lo.x && x + 0.5 + r <= hi.x && y + 0.5 - r >= lo.y && y + 0.5 + r <= hi.y;
        EXPECT_EQ(SplattingCamera::uniform_in_pixel(IVec2(x, y), lo, hi, Vec2(r)), inside)
            << "pixel " << x << ", " << y << ", radius " << r;
        uniform += inside;
      }
    // pbrt-v4's default Gaussian (radius 1.5): a ring one pixel wide draws through the filter.
    if (r == 1.5f) EXPECT_EQ(uniform, 14 * 9);
    // Up to half a pixel the filter never leaves its own square: every pixel is uniform.
    if (r <= 0.5f) EXPECT_EQ(uniform, 16 * 11);
  }
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
