// The screen window of pbrt-v4's projective cameras (perspective, orthographic): the rectangle of
// the image plane (x0 x1 y0 y1) that the film covers, raster y growing downwards and screen y
// upwards. By default the shorter image axis spans [-1, 1] ("frameaspectratio" replaces the
// image's aspect ratio in that rule). Its two parameters are declared here once.
#pragma once
#include "core/math.h"
#include "scene/param_spec.h"

namespace eyetrace {

// The window from the aspect ratio (the image's when `frame_aspect_ratio` <= 0).
Vec4 default_screen_window(IVec2 resolution, float frame_aspect_ratio = 0.f);

// The screen point of a raster position on the full film.
inline Vec2 screen_from_raster(const Vec4& window, IVec2 resolution, Vec2 p_raster) {
  return Vec2(window[0] + (p_raster.x / float(resolution.x)) * (window[1] - window[0]),
              window[3] - (p_raster.y / float(resolution.y)) * (window[3] - window[2]));
}

ParamSpec screen_window_param();
ParamSpec frame_aspect_ratio_param();
// "screenwindow" (x0 < x1, y0 < y1, else an error naming it), else the default window for
// "frameaspectratio" or the image.
Vec4 read_screen_window(const PluginParams& p, IVec2 resolution);

}  // namespace eyetrace
