// A box filter of one pixel whose sample() is the identity shift: film tests use it so that a
// sample's position and weight are exactly the ones the test chose.
#pragma once
#include "core/filter.h"

namespace eyetrace {

class UnitBox : public Filter {
 public:
  Vec2 radius() const override { return Vec2(0.5f); }
  float evaluate(Vec2) const override { return 1.f; }
  FilterSample sample(Vec2 u) const override { return {u - Vec2(0.5f), 1.f}; }
  float integral() const override { return 1.f; }
  bool constant() const override { return true; }
  std::string to_string() const override { return "box"; }
};

}  // namespace eyetrace
