// The auxiliary channels of pbrt-v4's GBufferFilm (src/pbrt/film.cpp), per pixel, from what
// each sample's camera ray first saw (core/visible_surface.h):
//   Albedo.R/G/B  the BSDF's albedo under the colour space's white, weighted by the filter and
//                 divided by all of the pixel's weight (pbrt-v4 does the same: rays that saw
//                 nothing darken it)
//   P.X/Y/Z, u, v the position and surface (u, v), averaged over the samples that saw a surface
//   dzdx, dzdy    how the depth (camera-space z) changes per pixel step: |average of dp/dx's z|,
//                 from ray differentials as pbrt-v4 makes them (set_position_differentials below)
//   N.X/Y/Z, Ns.X/Y/Z  geometric and shading normal, facing the camera: the normalised sum
//   Variance.R/G/B, RelativeVariance.R/G/B  of the samples' colour (unweighted, samples that saw
//                 a surface only): the sample variance and that over the mean (pbrt-v4's
//                 VarianceEstimator)
// in camera space ("coordinatesystem" "camera", pbrt-v4's default; a moving camera's at each sample's
// time, as pbrt-v4) or world space.
// Differences from pbrt-v4: the variance is of the output colour (linear sRGB times the film's scale), pbrt-v4's of the
// sensor RGB before its output matrix (for the default cie1931 sensor, of X, Y, Z).
#pragma once
#include <string>
#include <vector>

#include "core/animated_transform.h"
#include "core/camera.h"
#include "core/math.h"
#include "core/sampled_spectrum.h"
#include "core/transform.h"
#include "core/visible_surface.h"

namespace eyetrace {

class GBuffer {
 public:
  static constexpr int kChannels = 22;
  static const std::vector<std::string>& channel_names();  // in the order channels() writes them
  // Sums per pixel: p 3, n 3, ns 3, uv 2, albedo 3, surface weight, count, mean 3, m2 3, dzdx,
  // dzdy. Not part of the film's accumulators (checkpoints, MPI), which the gbuffer film
  // therefore refuses.
  static constexpr size_t kAccumulators = 26;

  // world_from_output: the camera's motion for camera space (a moving camera's space is taken at
  // each sample's time, as pbrt-v4 does), the identity for world space.
  GBuffer(size_t pixels, const AnimatedTransform& world_from_output);
  // A sample of weight w and colour `rgb` (linear sRGB before the film's scale) whose camera ray
  // saw `vs` (nothing when vs.set is false).
  void add(size_t pixel, const VisibleSurface& vs, const SampledWavelengths& lambda, const RGB& rgb, float w);
  // The pixel's kChannels values; film_weight is the pixel's whole weight, scale the film's.
  void channels(size_t pixel, double film_weight, float scale, float* out) const;

 private:
  std::vector<double> sums_;  // kAccumulators per pixel
  AnimatedTransform world_from_output_;
  Transform output_from_world_;  // at the start time: all a still camera needs
};

// Sets vs.dpdx and vs.dpdy for a sample whose camera ray `ray` (made from `sample`) saw vs: the
// rays of the same sample moved one pixel in x and in y (each tried +1 then -1 pixel: a lens
// camera may lose one of them) meet vs's tangent plane at p + dpdx and p + dpdy. That is
// pbrt-v4's perspective camera's ray differential (its other cameras take a 0.05-pixel finite
// difference: equal to first order) followed by SurfaceInteraction::ComputeDifferentials, and
// the differentials are scaled by max(1/8, 1/sqrt(spp)) as pbrt-v4's integrators scale them.
// Where a shifted ray is lost or runs parallel to the plane the differential stays zero (pbrt-v4
// then approximates it from the camera's smallest differentials).
void set_position_differentials(const Camera& camera, const CameraSample& sample, const Ray& ray, int spp,
                                VisibleSurface& vs);

}  // namespace eyetrace
