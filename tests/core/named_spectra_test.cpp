// All of pbrt-v4's named spectra (the 88 names of its namedSpectra table, mmp/pbrt-v4 at
// 5f7a606, src/pbrt/util/spectrum.cpp) are known, and the added tables give pbrt-v4's values:
// at its own samples exactly, between them linearly. Expected values are read off pbrt-v4's
// source by hand.
#include "core/named_spectra.h"
#include "../support/unity_id.h"

#include <gtest/gtest.h>

#include <string>

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

TEST(NamedSpectra, EveryPbrtV4NameIsKnown) {
  std::vector<std::string> names = {"glass-BK7",      "glass-BAF10",  "glass-FK51A",   "glass-LASF9",  "glass-F5",
                                    "glass-F10",      "glass-F11",    "metal-Ag-eta",  "metal-Ag-k",   "metal-Al-eta",
                                    "metal-Al-k",     "metal-Au-eta", "metal-Au-k",    "metal-Cu-eta", "metal-Cu-k",
                                    "metal-CuZn-eta", "metal-CuZn-k", "metal-MgO-eta", "metal-MgO-k",  "metal-TiO2-eta",
                                    "metal-TiO2-k",   "stdillum-A",   "stdillum-D50",  "stdillum-D65", "illum-acesD60"};
  for (int i = 1; i <= 12; ++i) names.push_back("stdillum-F" + std::to_string(i));
  for (const char* camera : {"canon_eos_100d", "canon_eos_1dx_mkii", "canon_eos_200d", "canon_eos_200d_mkii",
                             "canon_eos_5d", "canon_eos_5d_mkii", "canon_eos_5d_mkiii", "canon_eos_5d_mkiv",
                             "canon_eos_5ds", "canon_eos_m", "hasselblad_l1d_20c", "nikon_d810", "nikon_d850",
                             "sony_ilce_6400", "sony_ilce_7m3", "sony_ilce_7rm3", "sony_ilce_9"})
    for (const char* c : {"_r", "_g", "_b"}) names.push_back(std::string(camera) + c);
  ASSERT_EQ(names.size(), 88u);
  for (const std::string& n : names) EXPECT_NE(find_named_spectrum(n), nullptr) << n;
  EXPECT_EQ(named_spectrum_names().size(), 88u);
}

TEST(NamedSpectra, AddedTablesHavePbrtV4Values) {
  struct Case {
    const char* name;
    float lambda, value;
  };
  const Case cases[] = {
      {"metal-CuZn-eta", 550.f, 0.527f},
      {"metal-CuZn-eta", 555.f, 0.5f * (0.527f + 0.505f)},  // halfway between samples
      {"metal-CuZn-k", 600.f, 3.253f},
      {"metal-MgO-eta", 589.258972f, 1.73737f},
      {"metal-TiO2-eta", 499.919006f, 3.03f},
      {"metal-TiO2-k", 412.031006f, 0.022f},
      {"stdillum-F1", 435.f, 43.669998f},
      {"stdillum-F2", 405.f, 15.69f},
      {"illum-acesD60", 560.f, 100.f},
      {"canon_eos_5d_g", 380.f, 0.0013068288f},
      {"canon_eos_5d_g", 390.f, 0.000843798899999999f},
  };
  for (const Case& c : cases) {
    const NamedSpectrum* s = find_named_spectrum(c.name);
    ASSERT_NE(s, nullptr) << c.name;
    EXPECT_NEAR(evaluate_named_spectrum(*s, c.lambda), c.value, 1e-6f * std::max(1.f, c.value)) << c.name;
  }
  EXPECT_EQ(find_named_spectrum("stdillum-F7")->kind, NamedSpectrumKind::Illuminant);
  EXPECT_EQ(find_named_spectrum("metal-TiO2-k")->kind, NamedSpectrumKind::Metal);
  EXPECT_EQ(find_named_spectrum("nikon_d850_b")->kind, NamedSpectrumKind::Sensor);
}

TEST(NamedSpectra, TablesAreIncreasingPairs) {
  for (const std::string& n : named_spectrum_names()) {
    const NamedSpectrum& s = *find_named_spectrum(n);
    if (s.analytic) continue;
    ASSERT_EQ(s.interleaved.size() % 2, 0u) << n;
    ASSERT_GE(s.interleaved.size(), 4u) << n;
    for (size_t i = 2; i < s.interleaved.size(); i += 2) EXPECT_LT(s.interleaved[i - 2], s.interleaved[i]) << n;
  }
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
