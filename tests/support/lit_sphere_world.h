// The render tests' small world: a diffuse sphere on a floor disk of the given radius, lit by a
// point light from above left, over a black background (the view's first rows are black sky).
#pragma once
#include <fmt/format.h>

#include <string>

namespace eyetrace::test {

inline std::string lit_sphere_world(double floor_radius) {
  return fmt::format(R"(WorldBegin
LightSource "point" "point3 from" [2 3 -3] "rgb I" [20 20 20]
Material "diffuse" "rgb reflectance" [0.6 0.5 0.4]
Shape "sphere" "float radius" 1
Translate 0 -1 0
Rotate 90 1 0 0
Shape "disk" "float radius" {}
)",
                     floor_radius);
}

}  // namespace eyetrace::test
