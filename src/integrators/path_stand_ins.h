// pbrt-v4's "bdpt" integrator, rendered by the path tracer with a warning. Bidirectional
// path tracing is unbiased: it converges to the image the path tracer converges to, except for
// light that only a light-side path can carry (a caustic of a point or spot light seen through
// a specular surface), which the path tracer misses. Its own parameters are accepted and
// checked as pbrt-v4 does, so that a scene asking for it renders unmodified. ("sppm" is
// integrators/sppm_integrator.h.)
#pragma once
#include "integrators/path_integrator.h"

namespace eyetrace {

const PluginSpec& bdpt_integrator_spec();
std::unique_ptr<Integrator> create_bdpt_integrator(const IntegratorContext& ctx);

}  // namespace eyetrace
