// One pixel's state in stochastic progressive photon mapping (Hachisuka and Jensen 2009, as
// pbrt-v4's SPPMIntegrator keeps it): the direct light its camera paths saw, its visible point
// of the current iteration, and the photon statistics that shrink its search radius.
#pragma once
#include <cstdint>

#include "core/math.h"
#include "core/sampled_spectrum.h"

namespace eyetrace {

class BSDF;

// Where the pixel's camera path of this iteration stopped to gather photons. Its BSDF lives in
// the camera pass's scratch buffer until the iteration ends.
struct VisiblePoint {
  Vec3 p{0.f};
  Vec3 wo{0.f};
  const BSDF* bsdf = nullptr;  // null: no visible point this iteration
  SampledSpectrum beta{0.f};   // camera path throughput to p, camera weight included
  bool secondary_terminated = false;
};

struct SppmPixel {
  double radius = 0;
  double ld[3] = {0, 0, 0};   // direct light (camera-path emission and light sampling), sum over iterations, RGB
  double tau[3] = {0, 0, 0};  // flux gathered within the radius, rescaled as the radius shrinks, RGB
  double n = 0;               // photons the estimate accumulated (N)
  // This iteration's photons: their flux (RGB) and count (M).
  double phi[3] = {0, 0, 0};
  uint64_t m = 0;
  VisiblePoint vp;
};

// The progressive radius reduction after an iteration: with M new photons, N grows by gamma M
// and the radius shrinks so that r'^2 = r^2 (N + gamma M) / (N + M); the flux is rescaled to the
// new disc, tau' = (tau + Phi) r'^2 / r^2 (Hachisuka and Jensen 2009, eqs. 8 and 11; pbrt-v4
// with gamma = 2/3). Clears this iteration's photons.
inline void sppm_update(SppmPixel& px, double gamma = 2.0 / 3.0) {
  if (px.m > 0) {
    const double m = double(px.m);
    const double n_new = px.n + gamma * m;
    const double r_new = px.radius * std::sqrt(n_new / (px.n + m));
    const double shrink = (r_new * r_new) / (px.radius * px.radius);
    for (int c = 0; c < 3; ++c) px.tau[c] = (px.tau[c] + px.phi[c]) * shrink;
    px.n = n_new;
    px.radius = r_new;
  }
  px.m = 0;
  px.phi[0] = px.phi[1] = px.phi[2] = 0;
  px.vp = VisiblePoint{};
}

// The pixel's radiance after `iterations` iterations of `photons` photons each (pbrt-v4's final
// estimate): the mean direct light plus the density estimate tau / (N_emitted pi r^2).
inline void sppm_estimate(const SppmPixel& px, int iterations, uint64_t photons, float out[3]) {
  const double emitted = double(iterations) * double(photons);
  const double area = kPiDouble * px.radius * px.radius;
  for (int c = 0; c < 3; ++c) out[c] = float(px.ld[c] / iterations + px.tau[c] / (emitted * area));
}

}  // namespace eyetrace
