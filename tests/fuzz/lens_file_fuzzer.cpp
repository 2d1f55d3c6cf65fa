// libFuzzer target: pbrt-v4 lens files (optics::parse_lens_file). An OpticsError is the
// expected rejection. A lens that parses is then traced: sequential_trace.h promises finite
// results for finite rays (lost rays reported by kind, never NaN), and the paraxial analysis
// may refuse (OpticsError) but not fail in any other way.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <glm/geometric.hpp>

#include "optics/lens_file.h"
#include "optics/optics_error.h"
#include "optics/paraxial.h"
#include "optics/sequential_trace.h"

namespace {

using namespace eyetrace::optics;

[[noreturn]] void violated(const char* what) {
  std::fprintf(stderr, "lens_file_fuzzer: invariant violated: %s\n", what);
  std::abort();
}

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

void check_result(const TraceResult& r) {
  if (!finite(r.ray.origin) || !finite(r.ray.direction)) violated("traced ray is not finite");
}

// A fan of rays across the entrance (forward) and from the film (reverse).
void trace_fan(const Prescription& p) {
  const CompiledSystem system(p);
  const double h = std::max(p.stop_diameter_mm(), 1e-3);
  const double film_z = system.vertex_z(system.image_index());
  for (int i = -4; i <= 4; ++i) {
    const double y = h * i / 4.0;
    check_result(system.trace_forward(Ray{{0.0, y, -1.0}, {0.0, 0.0, 1.0}}));
    check_result(system.trace_forward(Ray{{0.0, 0.0, -10.0}, glm::normalize(glm::dvec3(0.0, y, 10.0))}));
    check_result(system.trace_reverse(Ray{{0.0, y, film_z}, {0.0, 0.0, -1.0}}));
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  // The same text with the film placed by focusing (the other path through the reader).
  for (int focus = 0; focus < 2; ++focus) {
    LensFileOptions options;
    if (focus) options.focus_distance_m = 1.0;
    Prescription p;
    try {
      p = parse_lens_file(text, "fuzz.dat", options);
    } catch (const OpticsError&) {
      continue;
    }
    trace_fan(p);
    try {
      const ParaxialData d = paraxial_analysis(p);
      if (!std::isfinite(d.power_D) || !std::isfinite(d.back_focal_point_mm))
        violated("paraxial analysis returned a non-finite power or focal point");
    } catch (const OpticsError&) {
    }
  }
  return 0;
}
