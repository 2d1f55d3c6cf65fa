// pbrt-v4's "bdpt" and "sppm" integrators, rendered by the path tracer with a warning.
// Bidirectional path tracing is unbiased and stochastic progressive photon mapping is
// consistent: both converge to the image the path tracer converges to, except for light
// that only a light-side path can carry (a caustic of a point or spot light seen through a
// specular surface), which the path tracer misses. Their own parameters are accepted and
// checked as pbrt-v4 does, so that a scene asking for them renders unmodified.
#pragma once
#include "integrators/path_integrator.h"

namespace eyetrace {

const PluginSpec& bdpt_integrator_spec();
const PluginSpec& sppm_integrator_spec();
std::unique_ptr<Integrator> create_bdpt_integrator(const IntegratorContext& ctx);
std::unique_ptr<Integrator> create_sppm_integrator(const IntegratorContext& ctx);

}  // namespace eyetrace
