// libFuzzer target: eye prescriptions as JSON (optics::prescription_from_json_text), the
// format of data/eyes/*.json. An OpticsError is the expected rejection (malformed JSON
// included); a prescription that is accepted has passed validate() and must trace finitely.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "optics/optics_error.h"
#include "optics/prescription_io.h"
#include "optics/sequential_trace.h"

namespace {

using namespace eyetrace::optics;

[[noreturn]] void violated(const char* what) {
  std::fprintf(stderr, "prescription_json_fuzzer: invariant violated: %s\n", what);
  std::abort();
}

bool finite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  Prescription p;
  try {
    p = prescription_from_json_text(text, "fuzz.json");
  } catch (const OpticsError&) {
    return 0;
  }
  // Round trip: what is written must read back.
  try {
    prescription_from_json(prescription_to_json(p), "round trip");
  } catch (const OpticsError&) {
    violated("an accepted prescription does not read back after prescription_to_json");
  }
  const CompiledSystem system(p);
  const double film_z = system.vertex_z(system.image_index());
  for (int i = -4; i <= 4; ++i) {
    const TraceResult r = system.trace_reverse(Ray{{0.0, 0.5 * i, film_z}, {0.0, 0.0, -1.0}});
    if (!finite(r.ray.origin) || !finite(r.ray.direction)) violated("traced ray is not finite");
  }
  return 0;
}
