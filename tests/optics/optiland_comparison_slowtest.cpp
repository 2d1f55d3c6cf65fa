// The MTF, RMS wavefront error and Strehl ratio of the Navarro, Le Grand, Gullstrand and Kooijman
// eyes against Optiland 0.6.0, an independent optical design code (tests/data/optiland/: its
// real-ray trace and OPD map, the MTF from that map's autocorrelation in cycles per degree; how
// and why in tools/oracles/optiland_eyes.py and tests/data/optiland/README.md). Same case in both
// codes: relaxed eye, object at infinity, 589.3 nm, the paraxial entrance-pupil disc of 3 or 5 mm
// unclipped, fields 0 and 20 degrees, the OPD about the sphere centred on the chief ray's image
// on the retina. Tolerances, and the differences found, are in docs/wavefront.md ("Against
// Optiland").
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../support/unity_id.h"
#include "optics/eye_models.h"
#include "optics/mtf.h"
#include "optics/psf.h"
#include "optics/wavefront.h"

namespace eyetrace::optics {
namespace {
namespace EYETRACE_UNITY_ID {

using Row = std::map<std::string, std::string>;

std::vector<Row> read_csv(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::vector<std::string> header;
  std::vector<Row> rows;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();  // a CR LF file still reads
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> cells;
    std::stringstream s(line);
    for (std::string cell; std::getline(s, cell, ',');) cells.push_back(cell);
    if (header.empty()) {
      header = cells;
      continue;
    }
    Row row;
    for (size_t i = 0; i < header.size() && i < cells.size(); ++i) row[header[i]] = cells[i];
    rows.push_back(row);
  }
  return rows;
}

struct Ours {
  double rms_waves, rms_no_tilt_waves, strehl_at_chief_ray;
  std::vector<MtfPoint> mtf;
};

const std::vector<double> kFreqs{5.0, 10.0, 20.0, 30.0, 40.0, 60.0};

// RMS of the OPD samples about their least-squares plane (piston and tilt), equal-area samples;
// the plane by the normal equations of (1, x, y), solved by Cramer's rule.
double rms_without_tilt(const WavefrontResult& w) {
  double a[3][3] = {}, b[3] = {};
  for (size_t i = 0; i < w.opd_waves.size(); ++i) {
    const double v[3] = {1.0, w.pupil_points[i].x, w.pupil_points[i].y};
    for (int r = 0; r < 3; ++r) {
      b[r] += v[r] * w.opd_waves[i];
      for (int c = 0; c < 3; ++c) a[r][c] += v[r] * v[c];
    }
  }
  auto det = [](const double m[3][3]) {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  };
  double plane[3];
  for (int k = 0; k < 3; ++k) {
    double m[3][3];
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) m[r][c] = c == k ? b[r] : a[r][c];
    plane[k] = det(m) / det(a);
  }
  double sum2 = 0.0;
  for (size_t i = 0; i < w.opd_waves.size(); ++i) {
    const double d = w.opd_waves[i] - plane[0] - plane[1] * w.pupil_points[i].x - plane[2] * w.pupil_points[i].y;
    sum2 += d * d;
  }
  return std::sqrt(sum2 / static_cast<double>(w.opd_waves.size()));
}

// eyetrace's numbers for one case: the wavefront on a 256 grid (the phase of the steepest
// wavefront here, Gullstrand's at 20 degrees and 5 mm, 8 waves RMS, is then sampled), unclipped.
Ours ours(const std::string& model, double pupil_mm, double field_deg) {
  EyeOptions e;
  e.model = model;
  const Prescription p = make_eye(e);
  WavefrontOptions o;
  o.field_deg = field_deg;
  o.pupil_radius_mm = 0.5 * pupil_mm;
  o.grid = 256;
  const WavefrontResult w = trace_wavefront(p, o);
  const Psf psf = compute_psf(w, retinal_scale(p, field_deg, o.object_distance_m, 0.0));
  return {w.rms_sampled_waves, rms_without_tilt(w), psf.strehl_phasor, compute_mtf(psf, kFreqs)};
}

TEST(OptilandComparison, EyesAgreeWithOptiland) {
  const std::vector<Row> rows = read_csv(std::string(EYETRACE_SOURCE_DIR) + "/tests/data/optiland/eyes_mtf.csv");
  ASSERT_EQ(rows.size(), 16u);
  for (const Row& r : rows) {
    const std::string model = r.at("model");
    const double pupil = std::stod(r.at("pupil_mm")), field = std::stod(r.at("field_deg"));
    const std::string label = model + " " + r.at("pupil_mm") + " mm " + r.at("field_deg") + " deg";
    ASSERT_EQ(std::stoi(r.at("rays_lost")), 0) << label;
    const Ours o = ours(model, pupil, field);
    const double rms = std::stod(r.at("rms_waves")), no_tilt = std::stod(r.at("rms_no_tilt_waves"));
    EXPECT_NEAR(o.rms_no_tilt_waves, no_tilt, 0.005 * no_tilt) << label;
    std::printf("%s: rms %.6f / %.6f, no tilt %.6f / %.6f\n", label.c_str(), o.rms_waves, rms, o.rms_no_tilt_waves,
                no_tilt);
    const double strehl = std::stod(r.at("strehl_at_chief_ray"));
    EXPECT_NEAR(o.strehl_at_chief_ray, strehl, 0.01 + 0.02 * strehl) << label;
    for (const MtfPoint& m : o.mtf) {
      const std::string f = std::to_string(static_cast<int>(m.freq_cpd));
      // The largest difference found is 0.0018 (docs/wavefront.md); issue 15 asks that any above
      // 0.02 be explained.
      EXPECT_NEAR(m.tangential, std::stod(r.at("mtf_t_" + f)), 0.005) << label << " tangential " << f;
      EXPECT_NEAR(m.sagittal, std::stod(r.at("mtf_s_" + f)), 0.005) << label << " sagittal " << f;
    }
  }
}

// Navarro's spherical aberration over a 6 mm pupil (docs/wavefront.md: no published value of the
// 1985 eye's OSA c(4,0) was found; this is Optiland's, fitted to its OPD map by the oracle script).
TEST(OptilandComparison, NavarroSphericalAberrationAt6mm) {
  const std::vector<Row> rows =
      read_csv(std::string(EYETRACE_SOURCE_DIR) + "/tests/data/optiland/navarro_6mm_zernike.csv");
  ASSERT_EQ(rows.size(), 1u);
  EyeOptions e;
  e.model = "navarro";
  WavefrontOptions o;
  o.pupil_radius_mm = 3.0;
  o.grid = 256;
  const WavefrontResult w = trace_wavefront(make_eye(e), o);
  EXPECT_NEAR(w.zernike_um[4], std::stod(rows[0].at("c20_um")), 2e-4);
  EXPECT_NEAR(w.zernike_um[12], std::stod(rows[0].at("c40_um")), 2e-5);
  EXPECT_NEAR(w.zernike_um[24], std::stod(rows[0].at("c60_um")), 2e-5);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace::optics
