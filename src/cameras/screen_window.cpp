#include "cameras/screen_window.h"

namespace eyetrace {

Vec4 default_screen_window(IVec2 res, float frame) {
  if (frame <= 0.f) frame = float(res.x) / float(res.y);
  return frame > 1.f ? Vec4(-frame, frame, -1.f, 1.f) : Vec4(-1.f, 1.f, -1.f / frame, 1.f / frame);
}

ParamSpec screen_window_param() {
  return param::reals("screenwindow")
      .size(4)
      .shown_default("shorter axis spans [−1, 1]")
      .describe("x0 x1 y0 y1 of the image plane");
}

ParamSpec frame_aspect_ratio_param() {
  return param::real("frameaspectratio")
      .above(0)
      .describe("aspect for the default screen window instead of the image's");
}

Vec4 read_screen_window(const PluginParams& p, IVec2 resolution) {
  const std::vector<float> sw = p.get_floats("screenwindow");
  if (!sw.empty()) {
    if (sw[0] >= sw[1] || sw[2] >= sw[3]) p.fail("screenwindow", "needs x0 < x1, y0 < y1");
    return Vec4(sw[0], sw[1], sw[2], sw[3]);
  }
  return default_screen_window(resolution, p.has("frameaspectratio") ? p.get_float("frameaspectratio") : 0.f);
}

}  // namespace eyetrace
