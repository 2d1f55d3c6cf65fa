// A camera's shutter as pbrt-v4's CameraBase has it: "shutteropen" and "shutterclose" (scene
// time), over which each camera sample's time is spread. The same interval is the film's
// exposure time (scene_builder.cpp: shutter_seconds, which also refuses a shutter that never
// opens).
#pragma once
#include "scene/param_spec.h"

namespace eyetrace {

struct Shutter {
  float open = 0.f, close = 1.f;
  // pbrt-v4's CameraBase::SampleTime: u in [0, 1) spread over the interval. The default
  // shutter gives u itself, bit for bit.
  float time(float u) const { return (1.f - u) * open + u * close; }
};

inline ParamSpec shutter_open_param() {
  return param::real("shutteropen", 0)
      .describe("time the shutter opens (motion blur; with shutterclose, the film's exposure time)");
}
inline ParamSpec shutter_close_param() {
  return param::real("shutterclose", 1)
      .describe("time the shutter closes (motion blur; with shutteropen, the film's exposure time)");
}
inline Shutter read_shutter(const PluginParams& p) {
  return Shutter{p.get_float("shutteropen"), p.get_float("shutterclose")};
}

}  // namespace eyetrace
