// BSDF interface, in world space. Directions point away from the surface; f() excludes the
// cosine factor; pdf() is with respect to solid angle. Specular lobes return a sample whose
// pdf is the discrete probability of choosing the lobe and f already divided accordingly.
#pragma once
#include <optional>

#include "core/math.h"
#include "core/sampled_spectrum.h"

namespace eyetrace {

enum BxDFFlags : unsigned {
  kReflection = 1u,
  kTransmission = 2u,
  kDiffuse = 4u,
  kGlossy = 8u,
  kSpecular = 16u,
};

struct BSDFSample {
  SampledSpectrum f{0.f};
  Vec3 wi{0.f};
  float pdf = 0.f;
  unsigned flags = 0;
  float eta = 1.f;  // relative index crossed by a transmitted direction (1 for reflection)
  bool is_specular() const { return flags & kSpecular; }
};

class BSDF {
 public:
  virtual ~BSDF() = default;
  virtual SampledSpectrum f(const Vec3& wo, const Vec3& wi) const = 0;
  // uc: 1D sample to choose a lobe; u: 2D sample for the direction.
  virtual std::optional<BSDFSample> sample_f(const Vec3& wo, float uc, Vec2 u) const = 0;
  virtual float pdf(const Vec3& wo, const Vec3& wi) const = 0;
  virtual unsigned flags() const = 0;
};

}  // namespace eyetrace
