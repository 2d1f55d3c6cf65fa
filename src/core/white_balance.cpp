#include "core/white_balance.h"

#include <cmath>

#include "core/cie_tables.h"
#include "core/spectrum.h"

namespace eyetrace {

glm::dvec3 xyz_from_xy(glm::dvec2 xy) {
  if (xy.y == 0.0) return glm::dvec3(0.0);
  return glm::dvec3(xy.x / xy.y, 1.0, (1.0 - xy.x - xy.y) / xy.y);
}

glm::dvec2 xy_from_xyz(glm::dvec3 xyz) {
  const double sum = xyz.x + xyz.y + xyz.z;
  if (sum == 0.0) return glm::dvec2(0.0);
  return glm::dvec2(xyz.x / sum, xyz.y / sum);
}

namespace {
// glm matrices are column-major: build them from rows as written in the literature.
glm::dmat3 from_rows(glm::dvec3 r0, glm::dvec3 r1, glm::dvec3 r2) { return glm::transpose(glm::dmat3(r0, r1, r2)); }
}  // namespace

const glm::dmat3& bradford_lms_from_xyz() {
  static const glm::dmat3 m =
      from_rows({0.8951, 0.2664, -0.1614}, {-0.7502, 1.7135, 0.0367}, {0.0389, -0.0685, 1.0296});
  return m;
}

const glm::dmat3& bradford_xyz_from_lms() {
  // The exact inverse (Lindbloom prints it to 7 digits: 0.9869929 -0.1470543 0.1599627 ...).
  static const glm::dmat3 m = glm::inverse(bradford_lms_from_xyz());
  return m;
}

glm::dmat3 bradford_adaptation(glm::dvec3 source, glm::dvec3 target) {
  const glm::dvec3 src = bradford_lms_from_xyz() * (source / source.y);
  const glm::dvec3 dst = bradford_lms_from_xyz() * (target / target.y);
  glm::dmat3 scale(1.0);
  for (int i = 0; i < 3; ++i) scale[i][i] = dst[i] / src[i];
  return bradford_xyz_from_lms() * scale * bradford_lms_from_xyz();
}

glm::dmat3 bradford_adaptation(glm::dvec2 source_xy, glm::dvec2 target_xy) {
  return bradford_adaptation(xyz_from_xy(source_xy), xyz_from_xy(target_xy));
}

double white_balance_illuminant(double kelvin, double lambda_nm) {
  const double cct = kelvin * 1.4388 / 1.4380;
  if (cct < 4000.0) return planck(lambda_nm, cct);
  if (!(lambda_nm >= kCieLambdaMin && lambda_nm <= kCieLambdaMax)) return 0.0;
  // The CIE daylight locus (CIE 15: x_D in two pieces, y_D from x_D) and M1, M2.
  const double x = cct <= 7000.0 ? -4.6070e9 / (cct * cct * cct) + 2.9678e6 / (cct * cct) + 0.09911e3 / cct + 0.244063
                                 : -2.0064e9 / (cct * cct * cct) + 1.9018e6 / (cct * cct) + 0.24748e3 / cct + 0.237040;
  const double y = -3.0 * x * x + 2.870 * x - 0.275;
  const double m = 0.0241 + 0.2562 * x - 0.7341 * y;
  const double m1 = (-1.3515 - 1.7703 * x + 5.9114 * y) / m;
  const double m2 = (0.0300 - 31.4424 * x + 30.0717 * y) / m;
  const auto& t = cie_table();
  const double f = (lambda_nm - kCieLambdaMin) / kCieLambdaStep;
  const int i = std::min(int(f), kCieRows - 2);
  const double u = f - i;
  auto at = [&](int k) { return double(t[k].s0) + m1 * t[k].s1 + m2 * t[k].s2; };
  return (1.0 - u) * at(i) + u * at(i + 1);
}

}  // namespace eyetrace
