// Zernike wavefront files (optics/zernike_file.h): both orderings give the same coefficients at
// the OSA/ANSI indices of Thibos et al. 2002 (Table 2: j = 4 is (2, 0), j = 3 (2, -2), j = 5
// (2, 2), j = 12 (4, 0)), and every kind of bad input is an error naming file, line and value.
#include <cstdio>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "../support/unity_id.h"
#include "optics/optics_error.h"
#include "optics/zernike_file.h"

namespace eyetrace::optics {
namespace {
namespace EYETRACE_UNITY_ID {

// The message parse_zernike_text throws for `text`, or "" when it parses.
std::string error_of(const std::string& text) {
  try {
    parse_zernike_text(text, "eye.zer");
  } catch (const OpticsError& e) {
    return e.what();
  }
  return "";
}

void expect_error(const std::string& text, const std::string& where, const std::string& value) {
  const std::string e = error_of(text);
  ASSERT_FALSE(e.empty()) << text;
  EXPECT_NE(e.find(where), std::string::npos) << e;
  EXPECT_NE(e.find(value), std::string::npos) << e;
}

TEST(ZernikeFile, OsaPairsAtTheirIndices) {
  const ZernikeFile f = parse_zernike_text(
      "# exported by an aberrometer\n"
      "pupil_diameter_mm 6.0\n"
      "wavelength_nm 555   # green\n"
      "ordering osa\n"
      "\n"
      "3 -0.125\n"
      "4 0.25\n"
      "12 0.0625\n",
      "eye.zer");
  EXPECT_EQ(f.pupil_diameter_mm, 6.0);
  EXPECT_EQ(f.wavelength_nm, 555.0);
  EXPECT_EQ(f.max_order, 4);
  ASSERT_EQ(f.coefficients_um.size(), 15u);  // orders 0..4
  EXPECT_EQ(f.coefficients_um[3], -0.125);
  EXPECT_EQ(f.coefficients_um[4], 0.25);
  EXPECT_EQ(f.coefficients_um[12], 0.0625);
  EXPECT_EQ(f.coefficients_um[5], 0.0);
}

TEST(ZernikeFile, NmTriplesGiveTheSameCoefficients) {
  const ZernikeFile f =
      parse_zernike_text("ordering nm\npupil_diameter_mm 5\n2 -2 -0.125\n2 0 0.25\n2 2 0.5\n4 0 0.0625\n", "eye.zer");
  EXPECT_EQ(f.wavelength_nm, 0.0);  // not stated
  ASSERT_EQ(f.coefficients_um.size(), 15u);
  EXPECT_EQ(f.coefficients_um[3], -0.125);
  EXPECT_EQ(f.coefficients_um[4], 0.25);
  EXPECT_EQ(f.coefficients_um[5], 0.5);
  EXPECT_EQ(f.coefficients_um[12], 0.0625);
  EXPECT_EQ(parse_zernike_text("ordering ansi\npupil_diameter_mm 5\n5 0.5\n", "a").coefficients_um[5], 0.5);
}

TEST(ZernikeFile, BadInputNamesFileLineAndValue) {
  const std::string head = "pupil_diameter_mm 6\nordering osa\n";
  expect_error("pupil_diameter_mm 6\nordering noll\n4 0.1\n", "eye.zer:2:", "'noll'");
  expect_error("ordering osa\n4 0.1\n", "eye.zer:", "pupil_diameter_mm");
  expect_error(head + "4 nan\n", "eye.zer:3:", "'nan'");
  expect_error(head + "4 inf\n", "eye.zer:3:", "'inf'");
  expect_error(head + "4 0.1\n4 0.2\n", "eye.zer:4:", "line 3");
  expect_error("pupil_diameter_mm 6\nordering nm\n2 0 0.1\n2 0 0.2\n", "eye.zer:4:", "j = 4");
  expect_error(head + "-1 0.1\n", "eye.zer:3:", "-1");
  expect_error(head + "66 0.1\n", "eye.zer:3:", "66");  // j = 66 is order 11
  expect_error("pupil_diameter_mm 6\nordering nm\n2 1 0.1\n", "eye.zer:3:", "(2, 1)");
  expect_error("pupil_diameter_mm 6\nordering nm\n12 0 0.1\n", "eye.zer:3:", "radial order 12");
  expect_error(head + "4 0.1 0.2\n", "eye.zer:3:", "3 fields");
  expect_error(head + "4x 0.1\n", "eye.zer:3:", "'4x'");
  expect_error(head + "4 150\n", "eye.zer:3:", "150");  // micrometres, not nanometres
  expect_error("pupil_diameter_mm 0\nordering osa\n4 0.1\n", "eye.zer:1:", "pupil_diameter_mm 0");
  expect_error("pupil_diameter_mm 6\npupil_diameter_mm 5\n", "eye.zer:2:", "line 1");
  expect_error("pupil_diameter_mm 6\nwavelength_nm 100\n", "eye.zer:2:", "100");
  expect_error("pupil_diameter_mm 6\n4 0.1\n", "eye.zer:2:", "ordering");
  expect_error("pupil 6\n", "eye.zer:1:", "'pupil'");
  expect_error(head, "eye.zer", "no coefficient");
  expect_error("pupil_diameter_mm 6\n", "eye.zer", "ordering");
}

TEST(ZernikeFile, ReadsAFileAndNamesOneItCannotOpen) {
  const std::string path = testing::TempDir() + "zernike_file_test.zer";
  {
    std::ofstream out(path);
    out << "pupil_diameter_mm 4\nordering osa\n5 -0.3\n";
  }
  const ZernikeFile f = read_zernike_file(path);
  EXPECT_EQ(f.origin, path);
  EXPECT_EQ(f.coefficients_um[5], -0.3);
  std::remove(path.c_str());
  try {
    read_zernike_file(path);
    FAIL() << "no error for a missing file";
  } catch (const OpticsError& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace::optics
