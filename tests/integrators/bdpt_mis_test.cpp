// The MIS weights of bidirectional path tracing (integrators/bdpt_mis.h) on random paths: for
// every path, the weights of the strategies the renderer uses (t >= 1 camera vertices with a
// camera that has importance, t >= 2 without (or for a camera ray off the film), both
// connection vertices non-specular, s = 0 only for a light that can be hit) sum to 1, which is
// what makes the estimator unbiased; and each equals the balance heuristic computed directly
// from the product of the vertex densities of its strategy (an independent formula).
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "../support/unity_id.h"
#include "integrators/bdpt_mis.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

// A path x_0 (camera) ... x_{n-1} (light): the density with which the camera side generates
// each vertex (fwd, walking away from the camera) and the light side (rev), and which are
// specular.
struct RandomPath {
  std::vector<double> from_camera, from_light;
  std::vector<bool> delta;
  bool delta_light = false;
};

RandomPath random_path(std::mt19937& rng, int n, double p_delta) {
  std::uniform_real_distribution<double> density(0.05, 20.0), coin(0.0, 1.0);
  RandomPath p;
  for (int i = 0; i < n; ++i) {
    p.from_camera.push_back(density(rng));
    p.from_light.push_back(density(rng));
    // The camera and the light vertex never scatter; interior vertices may be specular.
    p.delta.push_back(i > 0 && i < n - 1 && coin(rng) < p_delta);
  }
  p.delta_light = coin(rng) < 0.3;
  return p;
}

// Whether strategy (s, t) can make the path: its connection joins two non-specular vertices;
// s = 0 needs a light the camera path can hit.
bool usable(const RandomPath& p, int s, int t, int min_t) {
  const int n = int(p.delta.size());
  if (t < min_t) return false;
  if (s == 0) return !p.delta[size_t(n - 1)] && !p.delta_light;
  return !p.delta[size_t(t - 1)] && !p.delta[size_t(t)];
}

// The density of a strategy: camera-side densities for x_0 .. x_{t-1}, light-side ones for the
// rest. A specular vertex's direction is a delta shared by all strategies: it counts as 1.
double strategy_density(const RandomPath& p, int t) {
  double d = 1;
  for (size_t i = 0; i < p.delta.size(); ++i) {
    if (p.delta[i]) continue;
    d *= int(i) < t ? p.from_camera[i] : p.from_light[i];
  }
  return d;
}

// The inputs bdpt_mis_weight takes for strategy (s, t), as the integrator lays them out: a
// specular vertex has zero densities (pbrt-v4).
float weight_of(const RandomPath& p, int s, int t, int min_t) {
  std::vector<BdptDensities> cam(static_cast<size_t>(t)), light(static_cast<size_t>(s));
  for (int i = 0; i < t; ++i) {
    const bool d = p.delta[size_t(i)];
    cam[size_t(i)] = {d ? 0.f : float(p.from_camera[size_t(i)]), d ? 0.f : float(p.from_light[size_t(i)]), d};
  }
  const int n = s + t;
  for (int j = 0; j < s; ++j) {
    const size_t i = size_t(n - 1 - j);  // light vertex j is x_{n-1-j}
    const bool d = p.delta[i];
    light[size_t(j)] = {d ? 0.f : float(p.from_light[i]), d ? 0.f : float(p.from_camera[i]), d};
  }
  return bdpt_mis_weight(cam.data(), t, light.data(), s, p.delta_light, min_t);
}

void check_paths(int min_t, double p_delta) {
  std::mt19937 rng(1234 + min_t);
  int checked = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const int n = 3 + int(rng() % 8);  // 3 to 10 vertices: the s + t == 2 case is trivially 1
    const RandomPath p = random_path(rng, n, p_delta);
    double sum = 0, total_density = 0;
    for (int t = min_t; t <= n; ++t)
      if (usable(p, n - t, t, min_t)) total_density += strategy_density(p, t);
    if (total_density == 0) continue;  // no strategy can make this path
    for (int t = min_t; t <= n; ++t) {
      const int s = n - t;
      if (!usable(p, s, t, min_t)) continue;
      const double w = weight_of(p, s, t, min_t);
      // The balance heuristic directly: this strategy's density over the sum of all usable ones.
      EXPECT_NEAR(w, strategy_density(p, t) / total_density, 2e-5 * std::max(1.0, w)) << "n " << n << " t " << t;
      sum += w;
    }
    EXPECT_NEAR(sum, 1.0, 1e-4) << "n " << n;
    ++checked;
  }
  EXPECT_GT(checked, 1500);
}

TEST(BdptMis, WeightsOfAPathsStrategiesSumToOneWithoutLightTracing) { check_paths(2, 0.0); }

TEST(BdptMis, WeightsSumToOneWithSpecularVerticesAndDeltaLights) { check_paths(2, 0.3); }

TEST(BdptMis, WeightsSumToOneWithLightTracingStrategies) { check_paths(1, 0.3); }

TEST(BdptMis, ACameraRayThatHitsALightHasWeightOne) {
  const BdptDensities cam[2] = {{1.f, 1.f, false}, {0.5f, 3.f, false}};
  EXPECT_EQ(bdpt_mis_weight(cam, 2, nullptr, 0, false, 2), 1.f);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
