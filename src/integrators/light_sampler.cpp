#include "integrators/light_sampler.h"

namespace eyetrace {

PowerLightSampler::PowerLightSampler(const std::vector<const Light*>& lights) : lights_(lights) {
  if (lights_.empty()) return;
  std::vector<float> power;
  for (size_t i = 0; i < lights_.size(); ++i) {
    float p = lights_[i]->power();
    power.push_back(std::isfinite(p) && p > 0.f ? p : 0.f);
    index_[lights_[i]] = i;
  }
  // A scene whose lights all report zero power still gets uniform selection.
  bool any = false;
  for (float p : power) any |= p > 0.f;
  if (!any) std::fill(power.begin(), power.end(), 1.f);
  distrib_ = std::make_unique<PiecewiseConstant1D>(power);
}

const Light* PowerLightSampler::sample(float u, float* pmf) const {
  if (lights_.empty()) return nullptr;
  size_t i = distrib_->sample_discrete(u, pmf);
  return lights_[i];
}

float PowerLightSampler::pmf(const Light* light) const {
  auto it = index_.find(light);
  return it == index_.end() ? 0.f : distrib_->pmf(it->second);
}

}  // namespace eyetrace
