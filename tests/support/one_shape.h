// What the shape tests share: a parameter list of named floats, a scene holding one shape to
// shoot rays at, the message of the SceneError a call throws, and a vector comparison.
#pragma once
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "core/error.h"
#include "render/scene.h"

namespace eyetrace::test {

// "float NAME value" parameters at `file`:`line` (each parameter at column 9).
inline ParameterList float_params(const std::string& file, int line,
                                  const std::vector<std::pair<std::string, double>>& floats) {
  ParameterList pl(SourceLoc{file, line, 1});
  for (const auto& [name, value] : floats) {
    Param p;
    p.type = "float";
    p.name = name;
    p.loc = SourceLoc{file, line, 9};
    p.numbers = {value};
    pl.add(p);
  }
  return pl;
}

struct OneShape {
  std::unique_ptr<Scene> scene = std::make_unique<Scene>();
  const Shape* shape = nullptr;
  explicit OneShape(std::unique_ptr<Shape> s) {
    shape = s.get();
    scene->add_primitive(Primitive{std::move(s), nullptr, nullptr});
    scene->commit();
  }
  std::optional<SurfaceInteraction> hit(Vec3 o, Vec3 d, float tmax = kInfinity) const {
    SurfaceInteraction si;
    if (!scene->intersect(Ray{o, d, tmax}, &si)) return std::nullopt;
    return si;
  }
};

inline std::string scene_error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(no error)";
}

inline void expect_near(const Vec3& a, const Vec3& b, float tol) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

}  // namespace eyetrace::test
