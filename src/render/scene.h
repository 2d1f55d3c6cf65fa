// The render-ready scene: owns every shape, material, texture and light, and the Embree
// BVH over the shapes (Embree does all ray-scene intersection). Built by scene_builder.cpp.
#pragma once
#include <embree3/rtcore.h>

#include <atomic>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "core/animated_transform.h"
#include "core/interaction.h"
#include "core/light.h"
#include "core/material.h"
#include "core/medium.h"
#include "core/shape.h"
#include "core/texture.h"
#include "core/transform.h"

namespace eyetrace {

// The rays a render traced, in Embree's form, as Scene::intersect and Scene::occluded handed
// them to Embree: for benchmarks that replay exactly those rays through Embree alone
// (bench/embree_rate_bench.cpp).
struct RayRecord {
  std::vector<RTCRay> closest;  // rtcIntersect1
  std::vector<RTCRay> shadow;   // rtcOccluded1
};

struct Primitive {
  std::unique_ptr<Shape> shape;
  const Material* material = nullptr;
  const Light* area_light = nullptr;
  MediumInterface media;  // vacuum on both sides unless a MediumInterface was in effect
};

class Scene {
 public:
  Scene();
  ~Scene();
  Scene(const Scene&) = delete;
  Scene& operator=(const Scene&) = delete;

  // Ownership of everything shapes and lights point to.
  template <typename T>
  T* own(std::unique_ptr<T> object) {
    T* raw = object.get();
    owned_.push_back(std::shared_ptr<void>(std::move(object)));
    return raw;
  }

  void add_primitive(Primitive prim);
  // Object instancing: a named group of primitives built once into its own BVH, then placed
  // any number of times.
  void define_instance(const std::string& name, std::vector<Primitive> prims);
  bool has_instance(const std::string& name) const;
  // The transform is shared, not copied: a scene of many instances keeps each one once (the
  // scene description that named it holds the same).
  void add_instance(const std::string& name, std::shared_ptr<const Transform> world_from_instance);
  void add_instance(const std::string& name, const Transform& world_from_instance) {
    add_instance(name, std::make_shared<const Transform>(world_from_instance));
  }
  // Motion blur: the object placed by a transform that moves during the shutter (an Embree
  // instance with two time steps; a hit is rebuilt with the transform at the ray's time).
  void add_instance(const std::string& name, const AnimatedTransform& world_from_instance);
  // A moving shape: its primitives, made in object space, placed as an unnamed moving instance.
  void add_moving_primitives(std::vector<Primitive> prims, const AnimatedTransform& world_from_object);
  // The same in two steps, for a moving shape inside an object: built once (an index for
  // place_moving_group, or -1 when it has no primitives), placed once per use of the object.
  int define_moving_group(std::vector<Primitive> prims);
  void place_moving_group(int group, const AnimatedTransform& world_from_object);
  void add_light(std::unique_ptr<Light> light);
  // The medium the camera sits in (pbrt-v4: the outside medium current at the Camera directive).
  void set_camera_medium(const Medium* medium);
  // Builds the BVH and runs light preprocessing. Call once, after everything is added.
  void commit();
  // From this many primitives on, a BVH (the root's own shapes, or a moving shape's) is built in
  // Embree's compact layout (RTC_SCENE_FLAG_COMPACT: leaves index the shared vertex buffer instead
  // of copying triangles). On a 10-million-triangle mesh that takes 0.64x the peak memory (1.01
  // against 1.58 GB); on the 204,800-triangle terrain, forced compact, Embree's traversal takes
  // 1.10x the time. Below a million primitives the memory saved is small, so speed wins
  // (docs/performance.md, "Big scenes").
  static constexpr size_t kCompactPrimitives = size_t(1) << 20;
  // An object (ObjectBegin) goes compact from fewer: instancing is how a scene grows beyond what
  // fits, and an instanced mesh is kept once, indexed, as pbrt-v4 keeps it. On 10,000 instances
  // of a 100,352-triangle mesh: 0.93x the peak memory, 1.11x the render's CPU time, which is
  // still 0.39x pbrt-v4's (docs/performance.md, "Big scenes").
  static constexpr size_t kCompactObjectPrimitives = size_t(1) << 16;

  // Closest hit along the ray up to ray.tmax. Thread-safe after commit().
  bool intersect(const Ray& ray, SurfaceInteraction* si) const;
  // Any hit in (0, ray.tmax). Thread-safe after commit().
  bool occluded(const Ray& ray) const;

  // While `record` is set, every ray given to Embree is appended to it (under a lock, so any
  // thread count works; meant for benchmarks). nullptr stops recording. The record must
  // outlive the recording.
  void record_rays(RayRecord* record);

  const std::vector<const Light*>& lights() const { return lights_; }
  const std::vector<const Light*>& infinite_lights() const { return infinite_lights_; }
  // Over the whole shutter for what moves.
  Bounds3 bounds() const { return bounds_; }
  // Whether anything the rays can hit moves (a moving instance or shape).
  bool has_motion() const { return motion_ != nullptr; }
  const Medium* camera_medium() const { return camera_medium_; }
  // Whether any ray can travel through a medium: the camera sits in one or a surface bounds one.
  bool has_media() const { return has_media_; }
  size_t primitive_count() const;  // triangles + analytic shapes, instances counted once
  RTCDevice device() const { return device_; }
  // The committed Embree scene, for benchmarks that time Embree's traversal alone.
  RTCScene embree_scene() const { return root_; }

 private:
  struct InstanceGroup;
  struct Placement;
  std::unique_ptr<InstanceGroup> build_group(std::vector<Primitive> prims, const std::string& what,
                                             size_t compact_from);
  void place(const InstanceGroup* group, std::shared_ptr<const Transform> start, const AnimatedTransform* motion,
             const std::string& what);
  float embree_time(float time) const { return motion_ ? motion_->fraction(time) : 0.f; }
  RTCDevice device_ = nullptr;
  RTCScene root_ = nullptr;
  std::vector<Primitive> prims_;  // directly placed primitives; geom_index_ maps a root geometry ID here
  std::map<std::string, std::unique_ptr<InstanceGroup>> groups_;
  std::vector<std::unique_ptr<InstanceGroup>> moving_groups_;  // unnamed: define_moving_group's
  std::vector<Placement> placements_;                          // indexed by Embree instance geometry ID (in root)
  std::vector<std::unique_ptr<Light>> light_store_;
  std::vector<const Light*> lights_, infinite_lights_;
  std::vector<std::shared_ptr<void>> owned_;
  std::vector<int> geom_kind_;  // per root geometry ID: 0 primitive, 1 instance
  std::vector<size_t> geom_index_;
  Bounds3 bounds_;
  bool committed_ = false;
  const Medium* camera_medium_ = nullptr;
  bool has_media_ = false;
  // The first moving transform added, whose TransformTimes (common to all) map a ray's time
  // to Embree's [0, 1]; null when nothing moves.
  std::unique_ptr<AnimatedTransform> motion_;
  std::atomic<RayRecord*> record_{nullptr};
  mutable std::mutex record_lock_;
};

}  // namespace eyetrace
