#include "samplers/pmj02bn_points.h"

#include <mutex>

#include "samplers/hash.h"
#include "samplers/lowdiscrepancy.h"

namespace eyetrace {

std::vector<std::array<uint32_t, 2>> make_pmj02_set(uint64_t seed) {
  const OwenScrambler scramble_x(uint32_t(mix_bits(seed))), scramble_y(uint32_t(mix_bits(seed) >> 32));
  std::vector<std::array<uint32_t, 2>> points(kPmj02bnPoints);
  for (uint32_t i = 0; i < kPmj02bnPoints; ++i)
    points[i] = {scramble_x(sobol_bits(i, 0)), scramble_y(sobol_bits(i, 1))};
  return points;
}

const std::vector<std::array<uint32_t, 2>>& pmj02bn_set(int index) {
  static std::once_flag once;
  static std::vector<std::vector<std::array<uint32_t, 2>>> sets;
  std::call_once(once, [] {
    for (int s = 0; s < kPmj02bnSets; ++s) sets.push_back(make_pmj02_set(0x706d6a3032626eull + uint64_t(s)));
  });
  return sets[size_t(index % kPmj02bnSets)];
}

}  // namespace eyetrace
