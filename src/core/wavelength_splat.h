// Where one wavelength of a camera sample counts on the film when a dispersive eye splats it with
// a smooth pixel filter's weights (core/splatting_camera.h, render/film.h add_splats).
#pragma once
#include "core/math.h"

namespace eyetrace {

// Where one wavelength of a sample counts: a block of pixels of the sample's tile and the
// filter's value at each, as the product wx[column] * wy[row] (Filter::evaluate_axis: every
// pixel filter eyetrace has is a product of one-dimensional ones).
struct WavelengthSplat {
  static constexpr int kMaxSpan = 8;  // pixels per axis: filters of radius up to 3.5 pixels
  IVec2 first{0};                     // the block's first pixel (absolute raster coordinates)
  int nx = 0, ny = 0;                 // its size; 0: the wavelength counts nowhere
  float wx[kMaxSpan] = {}, wy[kMaxSpan] = {};
};

}  // namespace eyetrace
