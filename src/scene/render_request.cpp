// The overrides of a render request, checked, and the setup built with them (render_request.h).
#include "scene/render_request.h"

#include <fmt/core.h>
#include <unistd.h>

#include <cstdio>

#include "core/error.h"
#include "scene/parser.h"

namespace eyetrace {

namespace {

// What the scene builder refuses by default: 3/4 of the physical memory (0 when unknown: no limit).
uint64_t default_memory_limit() {
  long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && page > 0 ? uint64_t(pages) * uint64_t(page) / 4 * 3 : 0;
}

}  // namespace

IVec2 parse_resolution(const std::string& s) {
  int w = 0, h = 0;
  char x = 0, extra = 0;
  if (std::sscanf(s.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || (x != 'x' && x != 'X') || w < 1 || h < 1 ||
      w > 32768 || h > 32768)
    throw_parameter_error({}, "--resolution", fmt::format("\"{}\": expected WxH with 1 <= W, H <= 32768", s));
  return IVec2(w, h);
}

Vec4 parse_crop(const std::string& s) {
  float v[4];
  char extra = 0;
  if (std::sscanf(s.c_str(), "%f,%f,%f,%f%c", &v[0], &v[1], &v[2], &v[3], &extra) != 4)
    throw_parameter_error({}, "--crop", fmt::format("\"{}\": expected four fractions x0,x1,y0,y1", s));
  if (!(v[0] >= 0 && v[0] < v[1] && v[1] <= 1 && v[2] >= 0 && v[2] < v[3] && v[3] <= 1))
    throw_parameter_error({}, "--crop", fmt::format("\"{}\": needs 0 <= x0 < x1 <= 1 and 0 <= y0 < y1 <= 1", s));
  return Vec4(v[0], v[1], v[2], v[3]);
}

RenderOverrides render_overrides(const RenderRequest& r) {
  RenderOverrides o;
  if (!r.camera.empty()) o.camera = parse_directive_text(r.camera, "Camera", "--camera");
  if (!r.resolution.empty()) o.resolution = parse_resolution(r.resolution);
  if (!r.crop.empty()) o.crop = parse_crop(r.crop);
  if (r.spp < 0 || r.spp > (1 << 24))
    throw_parameter_error({}, "--spp", fmt::format("{}: expected samples per pixel in [1, {}]", r.spp, 1 << 24));
  o.spp = r.spp;
  if (r.seed >= 0) o.seed = uint64_t(r.seed);
  if (!(r.max_memory_gib >= 0))
    throw_parameter_error({}, "--max-memory", fmt::format("{}: expected GiB >= 0", r.max_memory_gib));
  o.max_memory_bytes = r.max_memory_gib > 0 ? uint64_t(r.max_memory_gib * 1073741824.0) : default_memory_limit();
  o.output = r.output;
  return o;
}

RenderSetup build_requested_setup(const SceneDescription& scene, const RenderRequest& request) {
  return build_render_setup(scene, render_overrides(request));
}

}  // namespace eyetrace
