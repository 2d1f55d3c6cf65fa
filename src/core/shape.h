// Shape interface: a shape adds itself to the Embree scene as one geometry and turns
// Embree's hit record back into a SurfaceInteraction. Area lights sample shapes by area.
#pragma once
#include <embree3/rtcore.h>

#include <memory>
#include <vector>

#include "core/interaction.h"
#include "core/ray.h"
#include "core/texture.h"

namespace eyetrace {

struct ShapeSample {
  Vec3 p{0.f};
  Vec3 n{0.f, 0.f, 1.f};  // oriented like the shape's geometric normal (ReverseOrientation applied)
  Vec2 uv{0.f};
  float pdf_area = 0.f;  // density with respect to surface area
  Vec3 p_error{0.f};     // rounding-error bound of p, as SurfaceInteraction::p_error (last: aggregate order)
};

class Shape {
 public:
  virtual ~Shape() = default;
  // Creates and commits this shape's Embree geometry in `scene`; returns its geometry ID.
  virtual unsigned attach(RTCDevice device, RTCScene scene) const = 0;
  // The hit at distance `t` on primitive `prim_id` with Embree's barycentrics (u, v) and
  // geometric normal `ng` (object space of the geometry, as Embree reports it).
  virtual SurfaceInteraction interaction(const Ray& ray, float t, unsigned prim_id, Vec2 uv, Vec3 ng) const = 0;
  virtual float area() const = 0;
  virtual ShapeSample sample_area(Vec2 u) const = 0;
  virtual Bounds3 bounds() const = 0;
  virtual size_t primitive_count() const { return 1; }
  // Alpha cut-outs seen by an area light on the shape (pbrt-v4's AlphaMasked): whether the
  // point `ctx` describes is cut away, so that it does not emit. Alpha between 0 and 1 masks a
  // fraction 1 - alpha of points, chosen by a hash of the point.
  virtual bool alpha_masked(const TextureEvalContext& ctx) const { return false; }
  // A constant alpha of 0: no ray ever meets the shape, yet pbrt-v4 lets an area light on it
  // emit everywhere, reached by light sampling only (its "invisible emitters").
  virtual bool invisible() const { return false; }
  // Why this shape cannot carry an area light, or null when it can (the scene builder turns a
  // refusal into an error at the shape's directive).
  virtual const char* emitter_refusal() const { return nullptr; }
  // What is approximate about this shape as an area light, or null when nothing is (the scene
  // builder warns only when the shape is one: a shape that does not emit is never area-sampled).
  virtual const char* emitter_caveat() const { return nullptr; }
};

}  // namespace eyetrace
