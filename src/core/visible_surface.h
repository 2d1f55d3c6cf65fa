// What a camera ray first sees (pbrt-v4's VisibleSurface, src/pbrt/film.h): the first surface
// with a BSDF along the ray (interfaces are passed through), for the gbuffer film's auxiliary
// channels. World space; normals face the camera (pbrt-v4's FaceForward to wo).
#pragma once
#include "core/math.h"
#include "core/sampled_spectrum.h"

namespace eyetrace {

struct SurfaceInteraction;
class BSDF;

struct VisibleSurface {
  bool set = false;  // false: the ray saw no surface (it escaped, or was lost)
  Vec3 p{0.f}, n{0.f}, ns{0.f};
  Vec2 uv{0.f};
  float time = 0.f;  // the camera ray's: where a moving camera was (the gbuffer's camera space)
  // How p moves on the surface's tangent plane per pixel step in x and y, scaled as pbrt-v4 scales
  // its ray differentials (render/gbuffer.h, set_position_differentials); zero when not computed.
  Vec3 dpdx{0.f}, dpdy{0.f};
  SampledSpectrum albedo{0.f};  // the BSDF's directional albedo towards the camera
};

// The visible surface at `si`; the albedo is pbrt-v4's estimate, BSDF::rho(wo) with the same 16
// fixed samples (src/pbrt/cpu/integrators.cpp, PathIntegrator::Li), so both renderers' albedo
// channels agree sample for sample on the same BSDF.
VisibleSurface visible_surface(const SurfaceInteraction& si, const BSDF& bsdf);

}  // namespace eyetrace
