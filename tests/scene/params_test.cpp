// ParameterList: a parameter given twice. pbrt-v4 keeps both copies and looks them up newest
// first, so the last value wins: measured with pbrt-v4 (5f7a606) on a sphere seen through a
// perspective camera with "float fov" 10 "float fov" 90, whose image is the one of fov 90
// alone (mean 0.9695; fov 10 alone: 0, the sphere fills the view). The collection's
// watercolor/camera-2.pbrt gives "focaldistance" and "lensradius" twice this way.
#include <gtest/gtest.h>

#include <stdexcept>

#include "../support/unity_id.h"
#include "core/error.h"
#include "scene/params.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

Param real(const std::string& type, const std::string& name, double v, int column) {
  Param p;
  p.type = type;
  p.name = name;
  p.loc = SourceLoc{"camera-2.pbrt", 15, column};
  p.numbers = {v};
  return p;
}

TEST(ParameterList, RepeatedParameterOfOneTypeKeepsTheLastValueWithAWarning) {
  WarningCollector warnings;
  ParameterList list;
  list.add(real("float", "focaldistance", 391, 5));
  list.add(real("float", "lensradius", 1, 30));
  list.add(real("float", "focaldistance", 114.5, 50));
  EXPECT_EQ(list.get_float("focaldistance", 0), 114.5f);
  EXPECT_EQ(list.get_float("lensradius", 0), 1.0f);
  EXPECT_EQ(list.params().size(), 2u);  // the first copy is gone: nothing left to report unused
  const auto w = warnings.warnings();
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0].loc.column, 50);
  EXPECT_NE(w[0].message.find("\"focaldistance\" given again (first at camera-2.pbrt:15:5)"), std::string::npos)
      << w[0].message;
}

// "point" and "point3" are one type: the repeat is the same parameter.
TEST(ParameterList, RepeatedParameterUnderAnAliasOfItsTypeIsTheSameParameter) {
  WarningCollector warnings;
  ParameterList list;
  Param a = real("point", "from", 1, 1), b = real("point3", "from", 2, 20);
  a.numbers = {1, 1, 1};
  b.numbers = {2, 2, 2};
  list.add(a);
  list.add(b);
  EXPECT_EQ(list.get_point3("from", Vec3{0, 0, 0}).x, 2.0);
  EXPECT_EQ(warnings.warnings().size(), 1u);
}

// Another type under the same name: pbrt-v4 would report the copy its plugin does not read as
// unused, so it stays an error at the second copy.
TEST(ParameterList, RepeatedNameWithAnotherTypeIsAnError) {
  ParameterList list;
  list.add(real("float", "radius", 1, 16));
  try {
    list.add(real("integer", "radius", 2, 33));
    FAIL() << "no error";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("parameter \"radius\" given twice (first at camera-2.pbrt:15:16)"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
