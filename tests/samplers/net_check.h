// The (0,2)-net property checked from its definition, shared by the pmj02bn point-set and
// sampler tests.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

namespace eyetrace::test {

// Whether points [0, 2^m) (32-bit fixed-point coordinates) hold one point in each elementary
// interval 2^-a x 2^-(m-a) of every shape a = 0..m, counted from the coordinates' digits.
inline bool is_02_net(const std::vector<std::array<uint32_t, 2>>& p, int m) {
  const size_t n = size_t(1) << m;
  for (int a = 0; a <= m; ++a) {
    std::vector<uint8_t> seen(n, 0);
    for (size_t i = 0; i < n; ++i) {
      const uint64_t x = a == 0 ? 0 : p[i][0] >> (32 - a), y = m - a == 0 ? 0 : p[i][1] >> (32 - (m - a));
      uint8_t& s = seen[(x << (m - a)) | y];
      if (s) return false;
      s = 1;
    }
  }
  return true;
}

}  // namespace eyetrace::test
