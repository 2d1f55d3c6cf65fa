// A transform that moves during the shutter (pbrt-v4's AnimatedTransform): two keyframes at
// the scene's TransformTimes, each decomposed into translation T, rotation R (a unit
// quaternion) and an upper-triangular scale-and-shear U, M = T R U; in between, T and U are
// interpolated linearly and R by slerp along the shorter arc. Outside [start, end] the
// transform holds its keyframe, as pbrt-v4's Interpolate does.
//
// pbrt-v4 factors the linear part by polar decomposition (R times a symmetric S); eyetrace
// factors it as Q R (R times an upper-triangular U) because that is the decomposition Embree
// interpolates (RTCQuaternionDecomposition), and the geometry Embree intersects must be the
// geometry whose hit point we rebuild here. The two agree whenever each keyframe is a rotation
// with a uniform scale (then U = S = s I), which covers rigid motion, LookAt cameras and
// uniform growth; they differ only for non-uniform scale combined with rotation.
#pragma once
#include <embree3/rtcore.h>

#include <glm/gtc/quaternion.hpp>

#include "core/math.h"
#include "core/transform.h"

namespace eyetrace {

class AnimatedTransform {
 public:
  AnimatedTransform() = default;  // not animated, identity
  explicit AnimatedTransform(const Transform& t) : start_(t), end_(t) {}
  // Throws std::domain_error when a keyframe is singular or projective, or when one keyframe
  // mirrors and the other does not (the motion would pass through a flat transform).
  AnimatedTransform(const Transform& start, float start_time, const Transform& end, float end_time);

  // False when both keyframes are the same matrix: nothing moves, interpolate() is start().
  bool is_animated() const { return animated_; }
  const Transform& start() const { return start_; }
  const Transform& end() const { return end_; }
  float start_time() const { return start_time_; }
  float end_time() const { return end_time_; }

  // Where in [0, 1] between the keyframes `time` falls: 0 at or before start_time, 1 at or after
  // end_time (also when end_time <= start_time: pbrt-v4 then jumps from start to end just after
  // start_time). This is the ray time Embree's two time steps take.
  float fraction(float time) const;
  // The transform at `time` (pbrt-v4's Interpolate, with the Q R factorisation above).
  Transform interpolate(float time) const;
  // The transform at fraction u in [0, 1] between the keyframes.
  Transform at_fraction(float u) const;
  // Embree's description of keyframe i (0 start, 1 end): the same T, R, U.
  RTCQuaternionDecomposition embree_keyframe(int i) const;

 private:
  struct Parts {
    Vec3 translation{0.f};
    glm::quat rotation{1.f, 0.f, 0.f, 0.f};
    glm::mat3 upper{1.f};  // upper triangular in row/column terms: upper[col][row] == 0 for row > col
  };
  static Parts decompose(const Transform& t);
  static Mat4 compose(const Vec3& translation, const glm::quat& rotation, const glm::mat3& upper);

  Transform start_, end_;
  float start_time_ = 0.f, end_time_ = 1.f;
  bool animated_ = false;
  Parts parts_[2];
};

// Where a possibly moving object is at `time`: `still` itself (no copy) unless `motion` moves,
// else the interpolated transform, kept in `scratch`. The cameras place each ray with it.
inline const Transform& placed_at(const AnimatedTransform& motion, const Transform& still, float time,
                                  Transform& scratch) {
  if (!motion.is_animated()) return still;
  scratch = motion.interpolate(time);
  return scratch;
}

}  // namespace eyetrace
