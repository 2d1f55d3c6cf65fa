#include "integrators/bdpt_mis.h"

namespace eyetrace {

namespace {

// A zero density is that of a specular choice, whose delta factor cancels in the ratio.
float remap0(float f) { return f != 0.f ? f : 1.f; }

}  // namespace

float bdpt_mis_weight(const BdptDensities* camera, int t, const BdptDensities* light, int s, bool delta_light,
                      int min_t) {
  if (s + t == 2) return 1.f;  // a camera ray that hits a light: the only strategy of this path
  float sum_ri = 0.f;
  // Strategies with fewer camera vertices: camera[i] generated from the light side instead.
  float ri = 1.f;
  for (int i = t - 1; i >= min_t; --i) {
    ri *= remap0(camera[i].pdf_rev) / remap0(camera[i].pdf_fwd);
    if (!camera[i].delta && !camera[i - 1].delta) sum_ri += ri;
  }
  // Strategies with fewer light vertices: light[i] generated from the camera side instead.
  ri = 1.f;
  for (int i = s - 1; i >= 0; --i) {
    ri *= remap0(light[i].pdf_rev) / remap0(light[i].pdf_fwd);
    const bool delta_before = i > 0 ? light[i - 1].delta : delta_light;
    if (!light[i].delta && !delta_before) sum_ri += ri;
  }
  return 1.f / (1.f + sum_ri);
}

}  // namespace eyetrace
