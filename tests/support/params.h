// A scene parameter of numbers ("float", "integer", "rgb", "point3", ...) for the tests that
// call plugin factories directly.
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "scene/params.h"

namespace eyetrace::test {

inline Param number_param(const std::string& type, const std::string& name, std::vector<double> numbers) {
  Param p;
  p.type = type;
  p.name = name;
  p.numbers = std::move(numbers);
  return p;
}

}  // namespace eyetrace::test
