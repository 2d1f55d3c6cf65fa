// Chooses a light for next-event estimation with probability proportional to its power, so
// bright lights get the shadow rays. The inverse map (light -> probability) serves MIS.
#pragma once
#include <memory>
#include <unordered_map>
#include <vector>

#include "core/distribution.h"
#include "core/light.h"

namespace eyetrace {

class PowerLightSampler {
 public:
  explicit PowerLightSampler(const std::vector<const Light*>& lights);
  // Returns null when the scene has no light.
  const Light* sample(float u, float* pmf) const;
  float pmf(const Light* light) const;
  bool empty() const { return lights_.empty(); }

 private:
  std::vector<const Light*> lights_;
  std::unique_ptr<PiecewiseConstant1D> distrib_;
  std::unordered_map<const Light*, size_t> index_;
};

}  // namespace eyetrace
