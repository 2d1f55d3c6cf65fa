// libFuzzer target: RGL tensor files (.bsdf, read by the "measured" material): parse_tensor_file
// and the BRDF checks of make_measured_brdf. A TensorFileError is the expected rejection; a BRDF
// that is accepted must evaluate, give densities and sample to finite values (no NaN or Inf can
// reach an image) for a spread of directions, including grazing and back-side ones.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "materials/measured_brdf.h"
#include "materials/measured_bxdf.h"

namespace {

void check(bool ok, const char* what) {
  if (ok) return;
  std::fprintf(stderr, "measured_bsdf_fuzzer: invariant violated: %s\n", what);
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace eyetrace;
  std::shared_ptr<const MeasuredBRDF> brdf;
  try {
    brdf = make_measured_brdf(parse_tensor_file(std::string_view(reinterpret_cast<const char*>(data), size)));
  } catch (const TensorFileError&) {
    return 0;
  }
  const MeasuredBxDF bxdf(brdf.get(), SampledWavelengths::sample_uniform(0.25f));
  const Vec3 dirs[] = {{0.f, 0.f, 1.f},        {0.6f, 0.f, 0.8f},   {-0.3f, 0.4f, 0.866f},
                       {0.999f, 0.f, 0.0447f}, {0.f, -0.6f, -0.8f}, {0.2f, 0.2f, 0.959f}};
  for (const Vec3& wo : dirs)
    for (const Vec3& wi : dirs) {
      check(is_finite(bxdf.f(wo, wi)), "f is not finite");
      const float pdf = bxdf.pdf(wo, wi);
      check(std::isfinite(pdf) && pdf >= 0.f, "pdf is negative or not finite");
    }
  for (const Vec3& wo : dirs)
    for (float u : {0.f, 0.13f, 0.5f, 0.87f, 0.99999994f})
      if (const auto s = bxdf.sample_f(wo, 0.5f, Vec2(u, 1.f - u))) {
        check(is_finite(s->f) && std::isfinite(s->pdf) && s->pdf > 0.f, "a sample is not finite");
        check(s->wi.z * wo.z > 0.f, "a sample is not a reflection");
      }
  return 0;
}
