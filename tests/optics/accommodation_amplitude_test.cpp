// Hofstetter's (1950) age-amplitude relations, checked at ages where the published formulas give
// round numbers (min 15 - 0.25 age, mean 18.5 - 0.3 age, max 25 - 0.4 age, never below 0), and
// the refusal of accommodation beyond the maximum, the message naming age, amplitude and relation.
// The produced accommodation is the refraction difference computed independently (tests/support).
#include <gtest/gtest.h>

#include "../support/meridian_refraction.h"
#include "../support/unity_id.h"
#include "optics/accommodation_amplitude.h"
#include "optics/eye_models.h"
#include "optics/optics_error.h"

namespace eyetrace::optics {
namespace {
namespace EYETRACE_UNITY_ID {

TEST(AccommodationAmplitude, HofstetterAtRoundAges) {
  const AccommodationAmplitude a20 = hofstetter_amplitude(20.0);
  EXPECT_DOUBLE_EQ(a20.minimum_D, 10.0);
  EXPECT_DOUBLE_EQ(a20.mean_D, 12.5);
  EXPECT_DOUBLE_EQ(a20.maximum_D, 17.0);
  const AccommodationAmplitude a60 = hofstetter_amplitude(60.0);
  EXPECT_NEAR(a60.minimum_D, 0.0, 1e-12);
  EXPECT_NEAR(a60.mean_D, 0.5, 1e-12);
  EXPECT_NEAR(a60.maximum_D, 1.0, 1e-12);
  const AccommodationAmplitude a80 = hofstetter_amplitude(80.0);  // every curve would be negative
  EXPECT_EQ(a80.minimum_D, 0.0);
  EXPECT_EQ(a80.mean_D, 0.0);
  EXPECT_EQ(a80.maximum_D, 0.0);
}

TEST(AccommodationAmplitude, BadAgesNameAge) {
  for (const double age : {-1.0, 121.0, std::nan("")}) {
    try {
      hofstetter_amplitude(age);
      FAIL() << age;
    } catch (const OpticsError& e) {
      EXPECT_EQ(e.option(), "age");
    }
  }
}

EyeOptions navarro(double accommodation_D, std::optional<double> age) {
  EyeOptions o;
  o.model = "navarro";
  o.accommodation_D = accommodation_D;
  o.age_years = age;
  return o;
}

TEST(AccommodationAmplitude, SixtyYearOldRefusesSixDioptres) {
  try {
    make_eye(navarro(6.0, 60.0));
    FAIL() << "no error";
  } catch (const OpticsError& e) {
    EXPECT_EQ(e.option(), "accommodation");
    for (const char* part : {"60-year-old", "1.00 D", "Hofstetter", "25 - 0.4 x age"})
      EXPECT_NE(e.message().find(part), std::string::npos) << part << " in " << e.message();
  }
  EXPECT_NO_THROW(make_eye(navarro(6.0, 20.0)));  // within 17 D
  EXPECT_NO_THROW(make_eye(navarro(0.0, 80.0)));  // a relaxed eye at any age
}

TEST(AccommodationAmplitude, LimitIsOnTheProducedAccommodation) {
  // Find by bisection the Navarro parameter whose produced accommodation (independent y-nu
  // refraction difference) is 1 D, the maximum at 60: just below is accepted, just above refused.
  const Prescription relaxed = make_eye(navarro(0.0, std::nullopt));
  const double r0 = test::meridian_refraction(relaxed, relaxed.surfaces[0].profile.curvature);
  auto produced = [&](double a) {
    const Prescription p = make_eye(navarro(a, std::nullopt));
    return r0 - test::meridian_refraction(p, p.surfaces[0].profile.curvature);
  };
  double lo = 0.0, hi = 3.0;
  for (int i = 0; i < 50; ++i) (produced(0.5 * (lo + hi)) < 1.0 ? lo : hi) = 0.5 * (lo + hi);
  EXPECT_NO_THROW(make_eye(navarro(lo - 1e-3, 60.0)));
  EXPECT_THROW(make_eye(navarro(hi + 1e-3, 60.0)), OpticsError);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace::optics
