// pbrt-v4 lens files: a good file (pbrt's dgauss.50mm layout, plus the conic extension) and bad
// files whose messages name the file and line.
#include <string>

#include <gtest/gtest.h>

#include "../support/unity_id.h"
#include "optics/lens_file.h"
#include "optics/optics_error.h"
#include "optics/paraxial.h"
#include "optics/sequential_trace.h"

namespace eyetrace::optics {
namespace {
namespace EYETRACE_UNITY_ID {

// Double-Gauss 50 mm as distributed with pbrt (US 2,673,491; Modern Lens Design p. 312,
// scaled to 50 mm): radius, thickness, index, aperture diameter; the stop row has index 0.
const char* kDoubleGauss = R"(# D-GAUSS F/2 22deg HFOV
# radius	axpos	N	aperture
29.475	3.76	1.67	25.2
84.83	0.12	1	25.2
19.275	4.025	1.67	23
40.77	3.275	1.699	23
12.75	5.705	1	18
0	4.5	0	17.1
-14.495	1.18	1.603	17
40.77	6.065	1.658	20
-20.385	0.19	1	20
437.065	3.22	1.717	20
-39.73	0	1	20
)";

TEST(LensFile, ParsesPbrtDoubleGauss) {
  const Prescription p = parse_lens_file(kDoubleGauss, "dgauss.50mm.dat");
  ASSERT_EQ(p.surfaces.size(), 12u);  // 11 interfaces + film
  EXPECT_EQ(p.stop_index(), 5);
  EXPECT_DOUBLE_EQ(p.stop_diameter_mm(), 17.1);
  EXPECT_DOUBLE_EQ(p.surfaces[0].semi_diameter_mm, 12.6);
  EXPECT_DOUBLE_EQ(p.surfaces[1].index_after, 1.0);
  EXPECT_DOUBLE_EQ(p.surfaces[5].index_after, 1.0);  // index 0 on the stop row = air
  EXPECT_NEAR(1.0 / p.surfaces[6].profile.curvature, -14.495, 1e-12);
  EXPECT_EQ(p.surfaces.back().role, SurfaceRole::Image);
  // Last thickness 0: film at the paraxial focus for infinity, i.e. refraction 0.
  EXPECT_NEAR(refraction_D(p), 0.0, 1e-9);
  const ParaxialData d = paraxial_analysis(p);
  EXPECT_NEAR(1000.0 / d.power_D, 50.0, 1.5);  // "scaled to 50 mm"
  // An axial ray reaches the film on the axis.
  const TraceResult t = CompiledSystem(p).trace_forward({{0, 0, -10}, {0, 0, 1}});
  ASSERT_TRUE(t.ok());
  EXPECT_NEAR(t.ray.origin.z, p.axial_length_mm(), 1e-12);
}

TEST(LensFile, FocusDistanceAndApertureOptions) {
  LensFileOptions o;
  o.focus_distance_m = 2.0;
  o.aperture_diameter_mm = 8.0;
  const Prescription p = parse_lens_file(kDoubleGauss, "dgauss.50mm.dat", o);
  EXPECT_NEAR(refraction_D(p), -0.5, 1e-9);
  EXPECT_DOUBLE_EQ(p.stop_diameter_mm(), 8.0);
  o.aperture_diameter_mm = 20.0;
  try {
    parse_lens_file(kDoubleGauss, "dgauss.50mm.dat", o);
    FAIL();
  } catch (const OpticsError& e) {
    EXPECT_STREQ(e.what(),
                 "dgauss.50mm.dat:8: aperture diameter 20 mm must be in (0, 17.1] mm "
                 "(the stop's diameter in the file)");
  }
}

TEST(LensFile, FilmAtTheLastThicknessAndConicColumn) {
  const char* text =
      "# singlet with a conic front\n"
      "0 2 0 10\n"
      "50 5 1.5 20 -1.0   # paraboloid\n"
      "-50 95 1 20\n";
  const Prescription p = parse_lens_file(text, "singlet.dat");
  EXPECT_DOUBLE_EQ(p.surfaces[1].profile.conic, -1.0);
  EXPECT_DOUBLE_EQ(p.axial_length_mm(), 2 + 5 + 95.0);
}

void expect_lens_error(const std::string& text, const std::string& message) {
  try {
    parse_lens_file(text, "lens.dat");
    ADD_FAILURE() << "no error; expected: " << message;
  } catch (const OpticsError& e) {
    EXPECT_EQ(std::string(e.what()), message);
  }
}

TEST(LensFile, BadFilesNameFileAndLine) {
  expect_lens_error("# c\n\n50 5 1.5 20\n0 2 0 10\n\n\n-50 95 1\n",
                    "lens.dat:7: expected 4 or 5 numbers (radius thickness index aperture [conic]), found 3");
  expect_lens_error("50 5 1.5 20\n0 2 x 10\n", "lens.dat:2: 'x' is not a number");
  expect_lens_error("50 5 1.5 20 1 2\n",
                    "lens.dat:1: expected 4 or 5 numbers (radius thickness index aperture [conic]), found 6");
  expect_lens_error("50 5 1.5 20\n-50 95 1 20\n",
                    "lens.dat: expected one aperture stop (a row with radius 0), found 0");
  expect_lens_error("0 1 0 10\n0 1 0 10\n50 5 1.5 20\n-50 95 1 20\n",
                    "lens.dat: expected one aperture stop (a row with radius 0), found 2");
  expect_lens_error("0 1 0 10\n50 -5 1.5 20\n", "lens.dat:2: thickness -5 mm is negative");
  expect_lens_error("0 1 0 10\n50 5 1.5 0\n", "lens.dat:2: aperture diameter 0 mm must be positive");
  expect_lens_error("# nothing\n", "lens.dat: no lens interfaces");
  // Semi-diameter 12 mm on a 10 mm sphere.
  expect_lens_error(
      "0 1 0 10\n10 5 1.5 24\n-50 95 1 20\n",
      "lens.dat: surface 1 'interface 1 (line 2)': semi-diameter 12 mm is beyond the conic's reach (max 10 mm)");
  EXPECT_THROW(read_lens_file("/nonexistent/lens.dat"), OpticsError);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace::optics
