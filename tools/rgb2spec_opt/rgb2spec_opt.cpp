// rgb2spec_opt: computes, at build time, the RGB -> spectrum table of Jakob & Hanika 2019
// ("A Low-Dimensional Function Space for Efficient Spectral Upsampling", EG 2019) for linear
// sRGB (Rec.709 primaries, D65 white), and writes it as a raw binary plus a one-statement C++
// file that embeds the binary with the assembler's .incbin (so compiling it takes no time).
//
//   rgb2spec_opt <resolution> <table.bin> <table.cpp>
//
// The model: a reflectance s(lambda) = S(p(lambda)) with p a quadratic polynomial and
// S(x) = 1/2 + x / (2 sqrt(1 + x^2)) a sigmoid, so every s lies in (0, 1). For each RGB of a
// grid the generator finds the three coefficients of p whose spectrum, seen under D65 by the
// CIE 1931 2-degree observer, has that RGB: Gauss-Newton (here Newton, since there are as
// many residuals as unknowns) on the CIELAB difference, with the analytic Jacobian.
//
// The grid (read by src/core/rgb_to_spectrum.cpp): for each of the three cases "component m
// is the largest", a res^3 grid over z = rgb[m] (at z_k = smoothstep(smoothstep(k / (res-1))),
// dense near 0 and 1), x = rgb[(m+1)%3] / z and y = rgb[(m+2)%3] / z (uniform in [0, 1]). Each
// case's solutions start from zero coefficients at the centre cell (x = y = 1/2, middle z),
// spread outwards over the middle z slice, each cell starting from its solved neighbour
// nearer the centre, and then walk up and down in z, each cell starting from the one before.
//
// Binary layout (native-endian, as the host that builds also runs it):
//   uint32 magic 'R2S1', uint32 resolution, uint32 0, uint32 0   (16 bytes)
//   float  z[res]
//   float  coefficients[3][res (z)][res (y)][res (x)][3]   (c0, c1, c2 for lambda in nm)
// This is a build tool: it is compiled with optimisation and without sanitizers in every
// build (see CMakeLists.txt) so that the table takes the same few seconds everywhere.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "../common/embedded_data.h"
#include "core/cie_tables.h"

namespace {

using Vec3d = std::array<double, 3>;
using Mat3d = std::array<Vec3d, 3>;

// ---- Quadrature: three-point Gauss-Legendre on each 5 nm interval of the CIE tables
// (380..780 nm), the tables interpolated linearly between their rows. On an interval the
// product of the interpolated table and illuminant is a quadratic, so the rule is exact for
// it times any spectrum that is cubic over 5 nm, and very nearly exact for a sigmoid: 240
// samples integrate the interpolated tables more accurately than Simpson at 1 nm (whose
// panels straddle the tables' kinks). The polynomial is fitted in t = (lambda - 380) / 400 in
// [0, 1], which keeps the three unknowns of similar size; the coefficients are converted to
// nm at the end.
constexpr double kLambdaMin = 380.0, kLambdaMax = 780.0;
constexpr int kIntervals = eyetrace::kCieRows - 1;
constexpr int kSamples = 3 * kIntervals;

struct Quadrature {
  std::array<double, kSamples> t{}, t2{};
  std::array<Vec3d, kSamples> w{};  // weight * (xbar, ybar, zbar) * D65, scaled so that white has Y = 1
  Vec3d white{};                    // XYZ of the perfect reflector under D65
};

Quadrature make_quadrature() {
  const auto& rows = eyetrace::cie_table();
  const double node[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)}, weight[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  Quadrature q;
  int n = 0;
  for (int r = 0; r < kIntervals; ++r) {
    const eyetrace::CieRow &a = rows[r], &b = rows[r + 1];
    const double half = 0.5 * (b.lambda_nm - a.lambda_nm);
    for (int g = 0; g < 3; ++g, ++n) {
      double f = 0.5 * (1.0 + node[g]);  // position in the interval, 0..1
      auto lerp = [f](float u, float v) { return (1.0 - f) * u + f * v; };
      double lambda = lerp(a.lambda_nm, b.lambda_nm);
      double w = weight[g] * half * lerp(a.d65, b.d65);
      q.t[n] = (lambda - kLambdaMin) / (kLambdaMax - kLambdaMin);
      q.t2[n] = q.t[n] * q.t[n];
      q.w[n] = {w * lerp(a.x, b.x), w * lerp(a.y, b.y), w * lerp(a.z, b.z)};
    }
  }
  double y_sum = 0.0;
  for (const auto& w : q.w) y_sum += w[1];
  for (auto& w : q.w)
    for (double& v : w) v /= y_sum;
  for (const auto& w : q.w)
    for (int c = 0; c < 3; ++c) q.white[c] += w[c];
  return q;
}

// ---- Linear algebra on 3x3.
bool solve3(Mat3d a, Vec3d b, Vec3d* x) {
  for (int col = 0; col < 3; ++col) {
    int pivot = col;
    for (int r = col + 1; r < 3; ++r)
      if (std::abs(a[r][col]) > std::abs(a[pivot][col])) pivot = r;
    if (!(std::abs(a[pivot][col]) > 1e-300)) return false;
    std::swap(a[col], a[pivot]);
    std::swap(b[col], b[pivot]);
    for (int r = col + 1; r < 3; ++r) {
      double f = a[r][col] / a[col][col];
      for (int c = col; c < 3; ++c) a[r][c] -= f * a[col][c];
      b[r] -= f * b[col];
    }
  }
  for (int r = 2; r >= 0; --r) {
    double s = b[r];
    for (int c = r + 1; c < 3; ++c) s -= a[r][c] * (*x)[c];
    (*x)[r] = s / a[r][r];
  }
  return std::isfinite((*x)[0]) && std::isfinite((*x)[1]) && std::isfinite((*x)[2]);
}

// Linear sRGB -> XYZ from the primaries' chromaticities and the white of the quadrature, so
// that RGB (1, 1, 1) is exactly the XYZ of the constant spectrum 1 (and greys stay flat).
Mat3d rgb_to_xyz_matrix(const Vec3d& white) {
  const double xy[3][2] = {{0.64, 0.33}, {0.30, 0.60}, {0.15, 0.06}};  // IEC 61966-2-1
  Mat3d p{};
  for (int c = 0; c < 3; ++c) {
    p[0][c] = xy[c][0] / xy[c][1];
    p[1][c] = 1.0;
    p[2][c] = (1.0 - xy[c][0] - xy[c][1]) / xy[c][1];
  }
  Vec3d s{};
  if (!solve3(p, white, &s)) std::abort();
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) p[r][c] *= s[c];
  return p;
}

// ---- CIELAB and its derivative.
constexpr double kDelta = 6.0 / 29.0;
double lab_f(double t) { return t > kDelta * kDelta * kDelta ? std::cbrt(t) : t / (3 * kDelta * kDelta) + 4.0 / 29.0; }
double lab_df(double t) {
  if (t > kDelta * kDelta * kDelta) {
    double c = std::cbrt(t);
    return 1.0 / (3.0 * c * c);
  }
  return 1.0 / (3 * kDelta * kDelta);
}
Vec3d xyz_to_lab(const Vec3d& xyz, const Vec3d& white) {
  double fx = lab_f(xyz[0] / white[0]), fy = lab_f(xyz[1] / white[1]), fz = lab_f(xyz[2] / white[2]);
  return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

class Solver {
 public:
  explicit Solver(const Quadrature& q) : q_(q) {}

  // Lab of the spectrum with coefficients c (in t) and, if jacobian is given, dLab/dc.
  Vec3d lab(const Vec3d& c, Mat3d* jacobian) const {
    Vec3d xyz{};
    Mat3d dxyz{};  // dxyz[channel][coefficient]
    for (int i = 0; i < kSamples; ++i) {
      double p = c[0] * q_.t2[i] + c[1] * q_.t[i] + c[2];
      double u = 1.0 + p * p, root = std::sqrt(u);
      double s = 0.5 + 0.5 * p / root;
      for (int k = 0; k < 3; ++k) xyz[k] += q_.w[i][k] * s;
      if (jacobian) {
        double ds = 0.5 / (u * root);
        for (int k = 0; k < 3; ++k) {
          double a = q_.w[i][k] * ds;
          dxyz[k][0] += a * q_.t2[i];
          dxyz[k][1] += a * q_.t[i];
          dxyz[k][2] += a;
        }
      }
    }
    const Vec3d& w = q_.white;
    if (jacobian) {
      double gx = lab_df(xyz[0] / w[0]) / w[0], gy = lab_df(xyz[1] / w[1]) / w[1], gz = lab_df(xyz[2] / w[2]) / w[2];
      for (int m = 0; m < 3; ++m) {
        (*jacobian)[0][m] = 116.0 * gy * dxyz[1][m];
        (*jacobian)[1][m] = 500.0 * (gx * dxyz[0][m] - gy * dxyz[1][m]);
        (*jacobian)[2][m] = 200.0 * (gy * dxyz[1][m] - gz * dxyz[2][m]);
      }
    }
    return xyz_to_lab(xyz, w);
  }

  struct Result {
    double residual;  // CIE76 difference at the solution
    int iterations;
  };

  // Newton's method with step halving from *c towards the target Lab; *c holds the result.
  Result solve(const Vec3d& target, Vec3d* c) const {
    constexpr int kMaxIterations = 100;
    constexpr double kTolerance = 1e-7;
    Mat3d j{};
    Vec3d lab_c = lab(*c, &j);
    double err = distance(lab_c, target);
    int it = 0;
    for (; it < kMaxIterations && err > kTolerance; ++it) {
      Vec3d r = {target[0] - lab_c[0], target[1] - lab_c[1], target[2] - lab_c[2]};
      Vec3d step{};
      if (!solve3(j, r, &step)) break;
      // The full step nearly always lowers the error: evaluate it with its Jacobian, and
      // halve it (evaluating the error alone) only when it does not.
      double alpha = 1.0;
      bool improved = false;
      for (int halving = 0; halving < 30; ++halving, alpha *= 0.5) {
        Vec3d trial = {(*c)[0] + alpha * step[0], (*c)[1] + alpha * step[1], (*c)[2] + alpha * step[2]};
        Mat3d j_trial{};
        Vec3d lab_trial = lab(trial, halving == 0 ? &j_trial : nullptr);
        double e = distance(lab_trial, target);
        if (e < err) {
          *c = trial;
          err = e;
          lab_c = lab_trial;
          j = halving == 0 ? j_trial : Mat3d{};
          if (halving > 0) lab_c = lab(*c, &j);
          improved = true;
          break;
        }
      }
      if (!improved) break;
    }
    return {err, it};
  }

 private:
  static double distance(const Vec3d& a, const Vec3d& b) {
    return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
  }
  const Quadrature& q_;
};

double smoothstep(double x) { return x * x * (3.0 - 2.0 * x); }

// Coefficients in t = (lambda - l0) / d to coefficients in lambda (nm).
std::array<float, 3> to_nanometres(const Vec3d& c) {
  const double l0 = kLambdaMin, d = kLambdaMax - kLambdaMin;
  double a = c[0] / (d * d), b = c[1] / d;
  return {float(a), float(b - 2.0 * a * l0), float(a * l0 * l0 - b * l0 + c[2])};
}


}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: %s <resolution> <table.bin> <table.cpp>\n", argv[0]);
    return 2;
  }
  const int res = std::atoi(argv[1]);
  if (res < 4 || res > 256) {
    std::fprintf(stderr, "rgb2spec_opt: resolution must be in 4..256, got '%s'\n", argv[1]);
    return 2;
  }
  const std::string bin_path = argv[2], cpp_path = argv[3];
  auto start = std::chrono::steady_clock::now();

  const Quadrature q = make_quadrature();
  const Mat3d rgb_to_xyz = rgb_to_xyz_matrix(q.white);
  const Solver solver(q);

  std::vector<float> z(res);
  for (int k = 0; k < res; ++k) z[k] = float(smoothstep(smoothstep(double(k) / (res - 1))));
  for (int k = 1; k < res; ++k) {
    if (!(z[k] > z[k - 1])) {  // the lookup divides by z[k] - z[k - 1]
      std::fprintf(stderr, "rgb2spec_opt: resolution %d is too fine for float z values\n", res);
      return 2;
    }
  }

  const size_t cells = size_t(res) * res * res;
  std::vector<float> table(3 * cells * 3);
  std::vector<Vec3d> solved(cells);  // one case's solutions in t, [k][j][i]
  auto at = [res](int k, int j, int i) { return (size_t(k) * res + j) * res + i; };

  double worst = 0.0, worst_rgb[3] = {0, 0, 0};
  long iterations = 0, unconverged = 0;
  const int mid = res / 2;

  for (int m = 0; m < 3; ++m) {
    auto solve_cell = [&](int k, int j, int i, Vec3d* c) {
      double rgb[3];
      rgb[m] = z[k];
      rgb[(m + 1) % 3] = double(i) / (res - 1) * z[k];
      rgb[(m + 2) % 3] = double(j) / (res - 1) * z[k];
      Vec3d xyz{};
      for (int r = 0; r < 3; ++r)
        xyz[r] = rgb_to_xyz[r][0] * rgb[0] + rgb_to_xyz[r][1] * rgb[1] + rgb_to_xyz[r][2] * rgb[2];
      Solver::Result result = solver.solve(xyz_to_lab(xyz, q.white), c);
      iterations += result.iterations;
      if (result.residual > 1e-3) ++unconverged;
      if (result.residual > worst) {
        worst = result.residual;
        std::copy(rgb, rgb + 3, worst_rgb);
      }
      solved[at(k, j, i)] = *c;
    };

    // The middle z slice, from its centre outwards (rings of growing Chebyshev distance),
    // each cell started from its neighbour one step nearer the centre.
    for (int ring = 0; ring <= res; ++ring) {
      for (int j = 0; j < res; ++j) {
        for (int i = 0; i < res; ++i) {
          int di = i - mid, dj = j - mid;
          if (std::max(std::abs(di), std::abs(dj)) != ring) continue;
          Vec3d c{0.0, 0.0, 0.0};
          if (ring > 0) c = solved[at(mid, j - (dj > 0) + (dj < 0), i - (di > 0) + (di < 0))];
          solve_cell(mid, j, i, &c);
        }
      }
    }
    // Then every (x, y) up and down in z. z = 0 is black, which no finite coefficients
    // reach: that row repeats the first row above it (at most z_1 off, 1.7e-6 at res 64;
    // the lookup returns exact black for RGB (0, 0, 0) without the table).
    for (int j = 0; j < res; ++j) {
      for (int i = 0; i < res; ++i) {
        Vec3d c = solved[at(mid, j, i)];
        for (int k = mid + 1; k < res; ++k) solve_cell(k, j, i, &c);
        c = solved[at(mid, j, i)];
        for (int k = mid - 1; k >= 1; --k) solve_cell(k, j, i, &c);
        solved[at(0, j, i)] = solved[at(1, j, i)];
      }
    }
    for (size_t cell = 0; cell < cells; ++cell) {
      std::array<float, 3> nm = to_nanometres(solved[cell]);
      for (int n = 0; n < 3; ++n) {
        if (!std::isfinite(nm[n])) {
          std::fprintf(stderr, "rgb2spec_opt: non-finite coefficient in case %d, cell %zu\n", m, cell);
          return 1;
        }
        table[(m * cells + cell) * 3 + n] = nm[n];
      }
    }
  }

  // The binary: header, z, coefficients.
  const uint32_t header[4] = {0x31533252u /* "R2S1" */, uint32_t(res), 0u, 0u};
  std::vector<unsigned char> bytes(sizeof(header) + z.size() * sizeof(float) + table.size() * sizeof(float));
  std::memcpy(bytes.data(), header, sizeof(header));
  std::memcpy(bytes.data() + sizeof(header), z.data(), z.size() * sizeof(float));
  std::memcpy(bytes.data() + sizeof(header) + z.size() * sizeof(float), table.data(), table.size() * sizeof(float));
  // The C++ file: three labelled slices of the binary in .rodata.
  const size_t z_offset = sizeof(header), coeff_offset = z_offset + z.size() * sizeof(float);
  const std::string comment = "// Generated by tools/rgb2spec_opt; do not edit. The sRGB -> spectrum table (see\n"
                              "// src/core/rgb_to_spectrum.h), embedded from the binary next to this file.\n"
                              "// resolution " + std::to_string(res) + "\n";
  if (!eyetrace::embed::write_embedded("rgb2spec_opt", bin_path, cpp_path, bytes, comment, "eyetrace_rgb2spec_srgb",
                             {{"eyetrace_rgb2spec_srgb_header", 0, sizeof(header)},
                              {"eyetrace_rgb2spec_srgb_z", z_offset, z.size() * sizeof(float)},
                              {"eyetrace_rgb2spec_srgb_coefficients", coeff_offset, table.size() * sizeof(float)}}))
    return 1;

  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf(
      "rgb2spec_opt: %d^3 x 3 cells in %.1f s (%.2f Newton iterations per cell); largest CIE76 residual %.2g at "
      "linear RGB (%.4g, %.4g, %.4g); %ld cells above 1e-3\n",
      res, seconds, double(iterations) / double(3 * cells), worst, worst_rgb[0], worst_rgb[1], worst_rgb[2],
      unconverged);
  return 0;
}
