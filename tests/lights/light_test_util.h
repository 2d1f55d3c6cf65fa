// Helpers shared by the light tests: parameter lists written in code, a reproducible
// uniform generator, and Pearson's chi-square test with its p-value.
// Everything is in an anonymous namespace: each test file gets its own copy.
#pragma once
#include <cmath>
#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "../support/spectral.h"
#include "core/light.h"
#include "core/spectrum.h"
#include "scene/params.h"

namespace eyetrace {
namespace {

inline Param num_param(const std::string& type, const std::string& name, std::vector<double> v) {
  Param p;
  p.type = type;
  p.name = name;
  p.loc = SourceLoc{"test.pbrt", 3, 7};
  p.numbers = std::move(v);
  return p;
}
inline Param float_param(const std::string& name, double v) { return num_param("float", name, {v}); }
inline Param rgb_param(const std::string& name, double r, double g, double b) {
  return num_param("rgb", name, {r, g, b});
}
inline Param point_param(const std::string& name, double x, double y, double z) {
  return num_param("point3", name, {x, y, z});
}
inline Param string_param(const std::string& name, const std::string& s) {
  Param p = num_param("string", name, {});
  p.strings = {s};
  return p;
}
inline Param bool_param(const std::string& name, bool b) {
  Param p = num_param("bool", name, {});
  p.bools = {b};
  return p;
}
inline ParameterList make_params(std::vector<Param> ps) {
  ParameterList list(SourceLoc{"test.pbrt", 3, 1});
  for (auto& p : ps) list.add(std::move(p));
  return list;
}

// The luminance one sample at wavelengths lambda estimates (unbiased over their draw).
inline float luminance_estimate(const SampledSpectrum& L, const SampledWavelengths& lambda) {
  return sampled_to_xyz(L, lambda).y;
}

// Luminance of the radiance light.sample_li(ctx, u) returns, integrated over wavelengths.
template <typename LightT>
float sample_luminance(const LightT& light, const LightSampleContext& ctx, Vec2 u) {
  return test::luminance_of([&](const SampledWavelengths& l) {
    auto s = light.sample_li(ctx, u, l);
    return s ? s->L : SampledSpectrum(0.f);
  });
}

// What the rays of Light::sample_le carry, for bidirectional path tracing: the mean over
// `count` samples of grey(L) |cos| / (pdf_pos pdf_dir), an estimate of the light's power in
// the units of Light::power() (grey: the value relative to a white emission of 1), with its
// standard error. Each sample's densities are also checked against pdf_le for the same ray
// (when check_pdf_le), and each sample by `check`.
struct LeEstimate {
  double power = 0, std_error = 0;
  int samples = 0;  // sample_le returned a ray
};
template <typename Check>
LeEstimate sample_le_power(const Light& light, int count, uint32_t seed, bool check_pdf_le, Check&& check) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u01(0.f, 0x1.fffffep-1f);
  const SampledWavelengths lambda = test::wavelengths();
  const float white = test::emission(1.f, lambda)[1];
  double sum = 0, sum2 = 0;
  LeEstimate e;
  for (int i = 0; i < count; ++i) {
    const Vec2 u1(u01(rng), u01(rng)), u2(u01(rng), u01(rng));
    const std::optional<LightLeSample> s = light.sample_le(u1, u2, lambda, 0.f);
    if (!s) continue;
    ++e.samples;
    EXPECT_NEAR(glm::length(s->ray.d), 1.f, 1e-5f);
    const float cos = s->n != Vec3(0.f) ? std::abs(glm::dot(s->n, s->ray.d)) : 1.f;
    const double x = double(s->L[1] / white) * cos / (double(s->pdf_pos) * s->pdf_dir);
    sum += x;
    sum2 += x * x;
    if (check_pdf_le) {
      float pos = -1.f, dir = -1.f;
      light.pdf_le(s->ray.o, s->n, s->ray.d, &pos, &dir);
      EXPECT_NEAR(dir, s->pdf_dir, 1e-4f * s->pdf_dir) << "sample " << i;
    }
    check(*s);
  }
  e.power = sum / count;
  e.std_error = std::sqrt(std::max(0.0, sum2 / count - e.power * e.power) / (count - 1));
  return e;
}

// Uniform floats in [0, 1) from a fixed seed: every run sees the same numbers.
class Uniform {
 public:
  explicit Uniform(uint32_t seed) : rng_(seed) {}
  float next() { return float(rng_() >> 8) * 0x1p-24f; }
  Vec2 next2() {
    float a = next();
    return Vec2(a, next());
  }

 private:
  std::mt19937 rng_;
};

// Regularised upper incomplete gamma Q(a, x) (series / continued fraction, Numerical Recipes 6.2).
inline double gamma_q(double a, double x) {
  if (x <= 0.0) return 1.0;
  double gln = std::lgamma(a);
  if (x < a + 1.0) {
    double ap = a, sum = 1.0 / a, del = sum;
    for (int n = 0; n < 1000; ++n) {
      ap += 1.0;
      del *= x / ap;
      sum += del;
      if (std::abs(del) < std::abs(sum) * 1e-15) break;
    }
    return 1.0 - sum * std::exp(-x + a * std::log(x) - gln);
  }
  double b = x + 1.0 - a, c = 1.0 / 1e-300, d = 1.0 / b, h = d;
  for (int i = 1; i < 1000; ++i) {
    double an = -i * (i - a);
    b += 2.0;
    d = an * d + b;
    if (std::abs(d) < 1e-300) d = 1e-300;
    c = b + an / c;
    if (std::abs(c) < 1e-300) c = 1e-300;
    d = 1.0 / d;
    double del = d * c;
    h *= del;
    if (std::abs(del - 1.0) < 1e-15) break;
  }
  return std::exp(-x + a * std::log(x) - gln) * h;
}

struct ChiSquareResult {
  double statistic = 0.0;
  int dof = 0;
  double p_value = 1.0;
  int impossible = 0;  // observations in cells whose expected count is zero
};

// Pearson's test of observed counts against expected ones. Cells expecting fewer than 5 are
// pooled (Mitsuba's convention) so the chi-square approximation holds.
inline ChiSquareResult chi_square(const std::vector<double>& observed, const std::vector<double>& expected) {
  ChiSquareResult r;
  double pool_obs = 0.0, pool_exp = 0.0;
  int cells = 0;
  for (size_t i = 0; i < observed.size(); ++i) {
    if (expected[i] <= 0.0) {
      if (observed[i] > 0.0) r.impossible += int(observed[i]);
      continue;
    }
    if (expected[i] < 5.0) {
      pool_obs += observed[i];
      pool_exp += expected[i];
      continue;
    }
    r.statistic += (observed[i] - expected[i]) * (observed[i] - expected[i]) / expected[i];
    ++cells;
  }
  if (pool_exp > 0.0) {
    r.statistic += (pool_obs - pool_exp) * (pool_obs - pool_exp) / pool_exp;
    ++cells;
  }
  r.dof = cells - 1;
  r.p_value = r.dof > 0 ? gamma_q(0.5 * r.dof, 0.5 * r.statistic) : 1.0;
  return r;
}

// Mean and standard error of a Monte Carlo estimator, from its samples.
struct Estimate {
  double mean = 0.0, std_error = 0.0;
};
inline Estimate estimate(const std::vector<double>& x) {
  double s = 0.0, s2 = 0.0;
  for (double v : x) s += v, s2 += v * v;
  double n = double(x.size());
  Estimate e;
  e.mean = s / n;
  double var = std::max(0.0, s2 / n - e.mean * e.mean);
  e.std_error = std::sqrt(var / (n - 1.0));
  return e;
}

}  // namespace
}  // namespace eyetrace
