// Inputs found by the lens-file and prescription fuzzers (tests/fuzz, tools/fuzz), kept with the
// message they must produce. Each once traced a NaN ray or escaped as a non-OpticsError.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "../support/unity_id.h"
#include "optics/lens_file.h"
#include "optics/optics_error.h"
#include "optics/prescription_io.h"
#include "optics/sequential_trace.h"

namespace eyetrace::optics {
namespace {
namespace EYETRACE_UNITY_ID {

std::string lens_error(const std::string& text, const LensFileOptions& options = {}) {
  try {
    parse_lens_file(text, "fuzz.dat", options);
  } catch (const OpticsError& e) {
    return e.what();
  }
  return "";
}

// An index of 1.7e192 overflowed eta^2 in Snell's law: NaN directions.
TEST(LensFileFuzzRegression, AbsurdIndexIsRejected) {
  LensFileOptions focus;
  focus.focus_distance_m = 1.0;
  const std::string message =
      lens_error("0\t4.5\t0\t17.1\n-14.495\t1.18\t3\t17\n40.77\t40.77\t" + std::string(190, '6') + "\t54\n", focus);
  EXPECT_NE(message.find("fuzz.dat: surface 2 'interface 2 (line 3)': index 6.66"), std::string::npos) << message;
  EXPECT_NE(message.find("is above 10"), std::string::npos) << message;
}

// A film 6.4e13 mm behind the lens: the intersection's squared distances lost every digit.
TEST(LensFileFuzzRegression, AbsurdThicknessIsRejected) {
  EXPECT_EQ(lens_error("#4\n0\t413\t0\t6.0\n2\t63777777777777\t3\t2"),
            "fuzz.dat: surface 1 'interface 1 (line 3)': thickness 63777777777777 mm is more than "
            "1000000 mm");
}

// The same geometry traced from that far away: round-off put the hit at the sphere's centre,
// where the surface gradient is zero; the result must stay finite (here: a lost ray).
TEST(LensFileFuzzRegression, RayFromFarAwayStaysFinite) {
  const CompiledSystem system(parse_lens_file("0\t413\t0\t6.0\n2\t3\t3\t2\n", "fuzz.dat"));
  const Ray ray{{0.0, 0.0, 413.0 + 63777777777777.0}, {0.0, 0.0, -1.0}};
  const TraceResult r = system.trace_range(ray, 1, 0);
  for (int i = 0; i < 3; ++i) {
    EXPECT_TRUE(std::isfinite(r.ray.origin[i])) << to_string(r.status);
    EXPECT_TRUE(std::isfinite(r.ray.direction[i])) << to_string(r.status);
  }
}

// nlohmann::json reports a number beyond double range as out_of_range, not parse_error.
TEST(PrescriptionJsonFuzzRegression, NumberOverflowIsAnOpticsError) {
  try {
    prescription_from_json_text("{\n \"format\": 222222E22222222 }", "fuzz.json");
    FAIL() << "accepted";
  } catch (const OpticsError& e) {
    EXPECT_NE(std::string(e.what()).find("fuzz.json: invalid JSON:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("number overflow"), std::string::npos) << e.what();
  }
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace::optics
