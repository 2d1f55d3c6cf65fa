// CIELAB, CIE76 and CIEDE2000; see ciede2000.h. The equation numbers are those of Sharma, Wu &
// Dalal 2005, section "Implementation of the CIEDE2000 color-difference formula".
#include "ciede2000.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace eyetrace::colour {

namespace {

constexpr double kDegrees = 180.0 / std::numbers::pi;
double sqr(double x) { return x * x; }
double cos_deg(double d) { return std::cos(d / kDegrees); }
double sin_deg(double d) { return std::sin(d / kDegrees); }

// CIE 1976: f(t) = t^(1/3) above (6/29)^3, the tangent line t / (3 (6/29)^2) + 4/29 below.
double lab_f(double t) {
  constexpr double d = 6.0 / 29.0;
  return t > d * d * d ? std::cbrt(t) : t / (3.0 * d * d) + 4.0 / 29.0;
}

}  // namespace

Lab xyz_to_lab(const std::array<double, 3>& xyz, const std::array<double, 3>& white) {
  double fx = lab_f(xyz[0] / white[0]), fy = lab_f(xyz[1] / white[1]), fz = lab_f(xyz[2] / white[2]);
  return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

double cie76(const Lab& p, const Lab& q) { return std::sqrt(sqr(p.L - q.L) + sqr(p.a - q.a) + sqr(p.b - q.b)); }

double ciede2000(const Lab& p, const Lab& q) {
  // (2)-(7): a' stretched by G, chroma C' and hue h' (degrees in [0, 360); 0 for zero chroma).
  const double pow25_7 = 6103515625.0;  // 25^7
  double c_ab_mean = 0.5 * (std::hypot(p.a, p.b) + std::hypot(q.a, q.b));
  double c7 = std::pow(c_ab_mean, 7.0);
  double g = 0.5 * (1.0 - std::sqrt(c7 / (c7 + pow25_7)));
  double a1 = (1.0 + g) * p.a, a2 = (1.0 + g) * q.a;
  double c1 = std::hypot(a1, p.b), c2 = std::hypot(a2, q.b);
  auto hue = [](double b, double a) {
    if (a == 0.0 && b == 0.0) return 0.0;
    double h = std::atan2(b, a) * kDegrees;
    return h < 0.0 ? h + 360.0 : h;
  };
  double h1 = hue(p.b, a1), h2 = hue(q.b, a2);

  // (8)-(10): differences.
  double dl = q.L - p.L, dc = c2 - c1;
  double dh = 0.0;
  if (c1 * c2 != 0.0) {
    dh = h2 - h1;
    if (dh > 180.0) dh -= 360.0;
    if (dh < -180.0) dh += 360.0;
  }
  double d_big_h = 2.0 * std::sqrt(c1 * c2) * sin_deg(0.5 * dh);

  // (11)-(14): means, the mean hue taken across the 0/360 seam when the hues are far apart.
  double l_mean = 0.5 * (p.L + q.L), c_mean = 0.5 * (c1 + c2);
  double h_mean = h1 + h2;
  if (c1 * c2 != 0.0) {
    if (std::abs(h1 - h2) <= 180.0)
      h_mean *= 0.5;
    else if (h1 + h2 < 360.0)
      h_mean = 0.5 * (h1 + h2 + 360.0);
    else
      h_mean = 0.5 * (h1 + h2 - 360.0);
  }

  // (15)-(22): weights and the rotation term.
  double t = 1.0 - 0.17 * cos_deg(h_mean - 30.0) + 0.24 * cos_deg(2.0 * h_mean) + 0.32 * cos_deg(3.0 * h_mean + 6.0) -
             0.20 * cos_deg(4.0 * h_mean - 63.0);
  double d_theta = 30.0 * std::exp(-sqr((h_mean - 275.0) / 25.0));
  double cm7 = std::pow(c_mean, 7.0);
  double r_c = 2.0 * std::sqrt(cm7 / (cm7 + pow25_7));
  double s_l = 1.0 + 0.015 * sqr(l_mean - 50.0) / std::sqrt(20.0 + sqr(l_mean - 50.0));
  double s_c = 1.0 + 0.045 * c_mean;
  double s_h = 1.0 + 0.015 * c_mean * t;
  double r_t = -sin_deg(2.0 * d_theta) * r_c;
  double tl = dl / s_l, tc = dc / s_c, th = d_big_h / s_h;
  return std::sqrt(std::max(0.0, tl * tl + tc * tc + th * th + r_t * tc * th));
}

}  // namespace eyetrace::colour
