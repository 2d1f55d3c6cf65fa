// pbrt-v4's "sppm" integrator, rendered by the path tracer with a warning (eyetrace's own
// "bdpt" is integrators/bdpt_integrator.h). Stochastic progressive photon mapping is
// consistent: it converges to the image the path tracer converges to, except for light
// that only a light-side path can carry (a caustic of a point or spot light seen through a
// specular surface), which the path tracer misses. Their own parameters are accepted and
// checked as pbrt-v4 does, so that a scene asking for them renders unmodified.
#pragma once
#include "integrators/path_integrator.h"

namespace eyetrace {

const PluginSpec& sppm_integrator_spec();
std::unique_ptr<Integrator> create_sppm_integrator(const IntegratorContext& ctx);

}  // namespace eyetrace
