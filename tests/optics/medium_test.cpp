// Dispersion laws against eye-models.md sections 3 and 5d.
#include <gtest/gtest.h>

#include "../support/unity_id.h"
#include "optics/medium.h"

namespace eyetrace::optics {
namespace {
namespace EYETRACE_UNITY_ID {

TEST(NavarroDispersion, WeightsSelectTheReferenceIndices) {
  // 5d: the weights are 1/0 at 365, 486.1, 656.3, 1014 nm to 1.4e-4 (coefficient rounding).
  const double wl[] = {365.0, 486.1, 656.3, 1014.0};
  for (int i = 0; i < 4; ++i) {
    std::array<double, 4> unit{};
    unit[i] = 1.0;
    for (int j = 0; j < 4; ++j)
      EXPECT_NEAR(navarro_herzberger_index(unit, wl[j]), i == j ? 1.0 : 0.0, 2e-4) << i << " " << j;
  }
}

TEST(NavarroDispersion, ReproducesTabulatedIndices) {
  // 5d "Formula values": 555 nm 1.37720 / 1.33864 / 1.42157 / 1.33724;
  // 587.6 nm 1.37602 / 1.33743 / 1.42001 / 1.33606.
  const std::array<double, 4> cornea{1.3975, 1.3807, 1.37405, 1.3668}, aqueous{1.3593, 1.3422, 1.3354, 1.3278},
      lens{1.4492, 1.4263, 1.4175, 1.4097}, vitreous{1.3565, 1.3407, 1.3341, 1.3273};
  EXPECT_NEAR(navarro_herzberger_index(cornea, 555), 1.37720, 2e-5);
  EXPECT_NEAR(navarro_herzberger_index(aqueous, 555), 1.33864, 2e-5);
  EXPECT_NEAR(navarro_herzberger_index(lens, 555), 1.42157, 2e-5);
  EXPECT_NEAR(navarro_herzberger_index(vitreous, 555), 1.33724, 2e-5);
  EXPECT_NEAR(navarro_herzberger_index(cornea, 587.6), 1.37602, 2e-5);
  EXPECT_NEAR(navarro_herzberger_index(lens, 587.6), 1.42001, 2e-5);
  // ES99 Table 1 at 458 nm (cornea 1.3828, lens 1.4292) to its 4 decimals (+1.5e-4).
  EXPECT_NEAR(navarro_herzberger_index(cornea, 458), 1.3828, 2e-4);
  EXPECT_NEAR(navarro_herzberger_index(lens, 458), 1.4292, 2e-4);
}

TEST(MediumIndex, AnchoredAtTheReferenceWavelength) {
  Medium m{"cornea", 1.376, 589.3, {}};
  m.dispersion.law = DispersionLaw::NavarroHerzberger;
  m.dispersion.herzberger_indices = {1.3975, 1.3807, 1.37405, 1.3668};
  EXPECT_EQ(m.index_at(589.3), 1.376);
  EXPECT_GT(m.index_at(450), m.index_at(650));  // normal dispersion
  const double raw_change = navarro_herzberger_index(m.dispersion.herzberger_indices, 450) -
                            navarro_herzberger_index(m.dispersion.herzberger_indices, 589.3);
  EXPECT_NEAR(m.index_at(450) - 1.376, raw_change, 1e-15);
  m.dispersion.law = DispersionLaw::None;
  EXPECT_EQ(m.index_at(450), 1.376);
}

TEST(MediumIndex, LeGrandCornuGivesLeGrandIndicesAt589) {
  // Section 3: n_inf + K/(lambda - 130) at 589.3 nm = 1.37714 / 1.33736 / 1.42004 / 1.33600.
  Dispersion d;
  d.law = DispersionLaw::Cornu;
  const double n_inf[] = {1.3610, 1.3221, 1.3999, 1.3208}, k[] = {7.4147, 7.0096, 9.2492, 6.9806},
               expected[] = {1.37714, 1.33736, 1.42004, 1.33600};
  for (int i = 0; i < 4; ++i) {
    d.cornu_n_inf = n_inf[i];
    d.cornu_k_nm = k[i];
    EXPECT_NEAR(d.evaluate(589.3), expected[i], 1e-5);
  }
}

TEST(MediumIndex, ArizonaAbbeLineThroughNd) {
  // Section 7: n(lambda) = nd + (lambda - 589.3)(nd - 1)/(Vd (486.1 - 656.3)).
  Medium m{"lens", 1.42, 589.3, {}};
  m.dispersion.law = DispersionLaw::AbbeLinear;
  m.dispersion.abbe_nd = 1.42;
  m.dispersion.abbe_vd = 51.9;
  EXPECT_NEAR(m.index_at(486.1) - m.index_at(656.3), 0.42 / 51.9, 1e-15);  // nF - nC = (nd-1)/Vd
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace::optics
