// The Embree side of the scene: one device, a root BVH over every shape and instance, and
// the mapping from Embree's hit record (geometry, instance and primitive IDs) back to the
// shape, material and emitter that own it.
#include "render/scene.h"

#include <map>
#include <mutex>
#include <stdexcept>

#include "core/error.h"
#include "core/float_error.h"

namespace eyetrace {

namespace {

// Embree reports errors through a callback that must not throw (it runs inside Embree's C
// API); it records the first message per device and the Scene turns it into a SceneError at
// its next checkpoint.
std::mutex g_error_mutex;
std::map<const void*, std::string> g_errors;  // by device

void embree_error_callback(void* device, RTCError code, const char* str) {
  if (code == RTC_ERROR_NONE) return;
  std::lock_guard<std::mutex> lock(g_error_mutex);
  std::string& message = g_errors[device];
  if (message.empty()) message = fmt::format("Embree error {}: {}", int(code), str ? str : "");
}

void check_embree(RTCDevice device, const std::string& what) {
  std::string message;
  {
    std::lock_guard<std::mutex> lock(g_error_mutex);
    auto it = g_errors.find(device);
    if (it == g_errors.end()) return;
    message = std::move(it->second);
    g_errors.erase(it);
  }
  if (!message.empty()) throw_error(fmt::format("{}: {}", what, message));
}

void forget_errors(RTCDevice device) {
  std::lock_guard<std::mutex> lock(g_error_mutex);
  g_errors.erase(device);
}

// Rays Embree must never see: non-finite origin or direction, a zero direction (no
// direction to report wo for) or an empty/NaN [0, tmax] interval.
bool traceable(const Ray& ray) {
  return is_finite(ray.o) && is_finite(ray.d) && (ray.d.x != 0.f || ray.d.y != 0.f || ray.d.z != 0.f) && ray.tmax > 0.f;
}

// `time`: the ray's time as Embree's fraction of the way between the two time steps of the
// moving instances (0 when nothing moves; Embree ignores it for geometry with one time step).
RTCRay to_embree(const Ray& ray, float time) {
  RTCRay r;
  r.org_x = ray.o.x, r.org_y = ray.o.y, r.org_z = ray.o.z;
  r.dir_x = ray.d.x, r.dir_y = ray.d.y, r.dir_z = ray.d.z;
  r.tnear = 0.f;
  r.tfar = ray.tmax;
  r.time = time;
  r.mask = 0xFFFFFFFFu;
  r.id = 0;
  r.flags = 0;
  return r;
}

Bounds3 transform_bounds(const Transform& t, const Bounds3& b) {
  Bounds3 out;
  if (b.empty()) return out;
  for (int corner = 0; corner < 8; ++corner) {
    Vec3 p((corner & 1) ? b.hi.x : b.lo.x, (corner & 2) ? b.hi.y : b.lo.y, (corner & 4) ? b.hi.z : b.lo.z);
    out.extend(t.point(p));
  }
  return out;
}

// A bound of the box over the motion: the boxes at 33 evenly spaced times, grown by 1 % of
// their diagonal, which covers the arc a corner sweeps between two of them (at most 1/32 of the
// rotation, shorter than 180 degrees, so the arc leaves its chord by under 0.2 % of its radius).
Bounds3 motion_bounds(const AnimatedTransform& motion, const Bounds3& b) {
  Bounds3 out;
  if (b.empty()) return out;
  constexpr int kSteps = 32;
  for (int i = 0; i <= kSteps; ++i) {
    Bounds3 at = transform_bounds(motion.at_fraction(float(i) / kSteps), b);
    out.extend(at.lo);
    out.extend(at.hi);
  }
  Vec3 pad(0.01f * glm::length(out.hi - out.lo));
  out.extend(out.lo - pad);
  out.extend(out.hi + pad);
  return out;
}

Vec3 normalized_or(const Vec3& v, const Vec3& fallback) {
  float len = glm::length(v);
  return (len > 0.f && std::isfinite(len)) ? v / len : fallback;
}

// An interaction computed in instance space, moved to world space: points by the transform,
// tangents as vectors, normals by the inverse transpose (as pbrt-v4 does for instances).
SurfaceInteraction to_world(const SurfaceInteraction& local, const Transform& world_from_instance) {
  SurfaceInteraction si = local;
  // pbrt's Transform rule for points with error: the instance transform's own rounding plus
  // the local bound carried through its linear part (core/float_error.h).
  si.p = transform_point_with_error(world_from_instance.matrix(), local.p, local.p_error, &si.p_error);
  si.n = normalized_or(world_from_instance.normal(local.n), local.n);
  si.ns = normalized_or(world_from_instance.normal(local.ns), si.n);
  if (glm::dot(si.ns, si.n) < 0.f) si.ns = -si.ns;
  si.dpdu = world_from_instance.vector(local.dpdu);
  si.dpdv = world_from_instance.vector(local.dpdv);
  return si;
}

}  // namespace

struct Scene::InstanceGroup {
  ~InstanceGroup() {
    if (scene) rtcReleaseScene(scene);
  }
  RTCScene scene = nullptr;
  std::vector<Primitive> prims;  // indexed by geometry ID inside `scene`
  Bounds3 bounds;
  size_t primitive_count = 0;
};

struct Scene::Placement {
  const InstanceGroup* group = nullptr;
  std::shared_ptr<const Transform> world_from_instance;  // at the start time
  std::unique_ptr<AnimatedTransform> motion;             // null when it does not move
};

Scene::Scene() {
  // Threads follow the hardware (Embree shares TBB's pool with the renderer); no thread
  // pinning, since the machine is shared with other processes.
  device_ = rtcNewDevice("set_affinity=0,verbose=0");
  if (!device_) throw_error(fmt::format("cannot create the Embree device (error {})", int(rtcGetDeviceError(nullptr))));
  rtcSetDeviceErrorFunction(device_, embree_error_callback, device_);
  root_ = rtcNewScene(device_);
  // ROBUST: eye models put thin, strongly curved surfaces close together; avoid Embree's
  // optimisations that trade accuracy for speed.
  rtcSetSceneFlags(root_, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(root_, RTC_BUILD_QUALITY_HIGH);
  check_embree(device_, "creating the scene");
}

Scene::~Scene() {
  // Embree scenes hold callbacks into the shapes: release them before the shapes go.
  // (Embree reference-counts: the device lives until the last scene is released.)
  if (root_) rtcReleaseScene(root_);
  groups_.clear();
  moving_groups_.clear();
  if (device_) {
    rtcReleaseDevice(device_);
    forget_errors(device_);
  }
}

void Scene::add_primitive(Primitive prim) {
  if (committed_) throw std::logic_error("Scene::add_primitive after commit()");
  if (!prim.shape) throw std::invalid_argument("Scene::add_primitive: null shape");
  has_media_ = has_media_ || prim.media.is_transition();
  unsigned id = prim.shape->attach(device_, root_);
  check_embree(device_, "adding a shape to the Embree scene");
  bounds_.extend(prim.shape->bounds());
  if (geom_kind_.size() <= id) {
    geom_kind_.resize(id + 1, -1);
    geom_index_.resize(id + 1, 0);
  }
  geom_kind_[id] = 0;
  geom_index_[id] = prims_.size();
  prims_.push_back(std::move(prim));
}

std::unique_ptr<Scene::InstanceGroup> Scene::build_group(std::vector<Primitive> prims, const std::string& what,
                                                         size_t compact_from) {
  for (const Primitive& p : prims) has_media_ = has_media_ || p.media.is_transition();
  auto group = std::make_unique<InstanceGroup>();
  group->scene = rtcNewScene(device_);
  rtcSetSceneFlags(group->scene, RTC_SCENE_FLAG_ROBUST);
  rtcSetSceneBuildQuality(group->scene, RTC_BUILD_QUALITY_HIGH);
  for (auto& prim : prims) {
    if (!prim.shape) throw std::invalid_argument("Scene: null shape in " + what);
    unsigned id = prim.shape->attach(device_, group->scene);
    check_embree(device_, "adding a shape to " + what);
    group->bounds.extend(prim.shape->bounds());
    group->primitive_count += prim.shape->primitive_count();
    if (group->prims.size() <= id) group->prims.resize(id + 1);
    group->prims[id] = std::move(prim);
  }
  if (group->primitive_count >= compact_from)
    rtcSetSceneFlags(group->scene, RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_COMPACT);
  // An instanced scene must be committed before any scene that instances it.
  rtcCommitScene(group->scene);
  check_embree(device_, "building " + what);
  return group;
}

void Scene::define_instance(const std::string& name, std::vector<Primitive> prims) {
  if (committed_) throw std::logic_error("Scene::define_instance after commit()");
  if (groups_.count(name)) throw_error(fmt::format("object \"{}\" is defined twice", name));
  groups_.emplace(name, build_group(std::move(prims), fmt::format("object \"{}\"", name), kCompactObjectPrimitives));
}

bool Scene::has_instance(const std::string& name) const { return groups_.count(name) != 0; }

void Scene::add_instance(const std::string& name, std::shared_ptr<const Transform> world_from_instance) {
  if (committed_) throw std::logic_error("Scene::add_instance after commit()");
  auto it = groups_.find(name);
  if (it == groups_.end()) throw_error(fmt::format("object \"{}\" is not defined", name));
  place(it->second.get(), std::move(world_from_instance), nullptr, fmt::format("object \"{}\"", name));
}

void Scene::add_instance(const std::string& name, const AnimatedTransform& world_from_instance) {
  if (!world_from_instance.is_animated()) return add_instance(name, world_from_instance.start());
  if (committed_) throw std::logic_error("Scene::add_instance after commit()");
  auto it = groups_.find(name);
  if (it == groups_.end()) throw_error(fmt::format("object \"{}\" is not defined", name));
  place(it->second.get(), std::make_shared<const Transform>(world_from_instance.start()), &world_from_instance,
        fmt::format("object \"{}\"", name));
}

void Scene::add_moving_primitives(std::vector<Primitive> prims, const AnimatedTransform& world_from_object) {
  int group = define_moving_group(std::move(prims));
  if (group >= 0) place_moving_group(group, world_from_object);
}

int Scene::define_moving_group(std::vector<Primitive> prims) {
  if (committed_) throw std::logic_error("Scene::define_moving_group after commit()");
  if (prims.empty()) return -1;
  moving_groups_.push_back(build_group(std::move(prims), "a moving shape", kCompactPrimitives));
  return int(moving_groups_.size()) - 1;
}

void Scene::place_moving_group(int group, const AnimatedTransform& world_from_object) {
  if (committed_) throw std::logic_error("Scene::place_moving_group after commit()");
  if (group < 0 || size_t(group) >= moving_groups_.size()) throw std::out_of_range("Scene::place_moving_group");
  place(moving_groups_[size_t(group)].get(), std::make_shared<const Transform>(world_from_object.start()),
        world_from_object.is_animated() ? &world_from_object : nullptr, "a moving shape");
}

void Scene::place(const InstanceGroup* group, std::shared_ptr<const Transform> start, const AnimatedTransform* motion,
                  const std::string& what) {
  if (group->prims.empty()) return;  // an empty object contributes nothing
  RTCGeometry geom = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_INSTANCE);
  rtcSetGeometryInstancedScene(geom, group->scene);
  if (motion) {
    // Two time steps at Embree times 0 and 1 (the TransformTimes; embree_time maps a ray's
    // time there), interpolated as AnimatedTransform does: T and S lerped, R slerped.
    rtcSetGeometryTimeStepCount(geom, 2);
    for (unsigned i = 0; i < 2; ++i) {
      RTCQuaternionDecomposition d = motion->embree_keyframe(int(i));
      rtcSetGeometryTransformQuaternion(geom, i, &d);
    }
  } else {
    rtcSetGeometryTimeStepCount(geom, 1);
    // glm matrices are column-major 4x4 floats, exactly Embree's FLOAT4X4_COLUMN_MAJOR.
    rtcSetGeometryTransform(geom, 0, RTC_FORMAT_FLOAT4X4_COLUMN_MAJOR, &start->matrix()[0][0]);
  }
  rtcCommitGeometry(geom);
  unsigned id = rtcAttachGeometry(root_, geom);
  rtcReleaseGeometry(geom);
  check_embree(device_, "placing " + what);
  bounds_.extend(motion ? motion_bounds(*motion, group->bounds) : transform_bounds(*start, group->bounds));
  if (geom_kind_.size() <= id) {
    geom_kind_.resize(id + 1, -1);
    geom_index_.resize(id + 1, 0);
  }
  geom_kind_[id] = 1;
  geom_index_[id] = placements_.size();
  placements_.push_back(
      Placement{group, std::move(start), motion ? std::make_unique<AnimatedTransform>(*motion) : nullptr});
  if (motion && !motion_) motion_ = std::make_unique<AnimatedTransform>(*motion);
}

void Scene::set_camera_medium(const Medium* medium) {
  camera_medium_ = medium;
  has_media_ = has_media_ || medium;
}

void Scene::add_light(std::unique_ptr<Light> light) {
  if (!light) throw std::invalid_argument("Scene::add_light: null light");
  lights_.push_back(light.get());
  if (light->is_infinite()) infinite_lights_.push_back(light.get());
  light_store_.push_back(std::move(light));
}

void Scene::commit() {
  if (committed_) throw std::logic_error("Scene::commit called twice");
  size_t own = 0;  // the root's own primitives: instanced groups decide for themselves
  for (const Primitive& p : prims_) own += p.shape->primitive_count();
  if (own >= kCompactPrimitives) rtcSetSceneFlags(root_, RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_COMPACT);
  rtcCommitScene(root_);
  check_embree(device_, "building the scene BVH");
  committed_ = true;
  // Lights need a finite extent even for an empty scene: use the origin.
  Bounds3 extent = bounds_;
  if (extent.empty()) extent.extend(Vec3(0.f));
  if (bounds_.empty()) bounds_ = extent;
  for (auto& light : light_store_) light->preprocess(extent);
}

bool Scene::intersect(const Ray& ray, SurfaceInteraction* si) const {
  if (!committed_) throw std::logic_error("Scene::intersect before commit()");
  if (!traceable(ray)) return false;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rh;
  rh.ray = to_embree(ray, embree_time(ray.time));
  if (RayRecord* rec = record_.load(std::memory_order_relaxed)) {
    std::lock_guard lock(record_lock_);
    rec->closest.push_back(rh.ray);
  }
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(root_, &context, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;

  float t = rh.ray.tfar;
  Vec2 uv(rh.hit.u, rh.hit.v);
  Vec3 ng(rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z);
  const Primitive* prim;
  if (rh.hit.instID[0] == RTC_INVALID_GEOMETRY_ID) {
    prim = &prims_[geom_index_[rh.hit.geomID]];
    *si = prim->shape->interaction(ray, t, rh.hit.primID, uv, ng);
  } else {
    const Placement& place = placements_[geom_index_[rh.hit.instID[0]]];
    prim = &place.group->prims[rh.hit.geomID];
    // A moving instance is rebuilt at the ray's time, the transform Embree intersected.
    Transform at_time;
    const Transform* inst = place.world_from_instance.get();
    if (place.motion) {
      at_time = place.motion->interpolate(ray.time);
      inst = &at_time;
    }
    // The same ray in instance space: t is unchanged because the direction is mapped
    // linearly without renormalisation.
    Ray local{Vec3(inst->inverse_matrix() * Vec4(ray.o, 1.f)), Vec3(inst->inverse_matrix() * Vec4(ray.d, 0.f)),
              ray.tmax, ray.time};
    *si = to_world(prim->shape->interaction(local, t, rh.hit.primID, uv, ng), *inst);
    // Embree interpolates the same T, R, S in its own float arithmetic (its slerp uses
    // polynomial acos and sin): the surface it traces and the one rebuilt here differ by a few
    // float steps (measured: at most 2.7e-7 of |p| over 20,000 hits on a turning, moving,
    // growing quad), which the error box must cover or a spawned ray could hit the surface it
    // leaves. 2e-6 of |p| is seven times that.
    if (place.motion) si->p_error += glm::abs(si->p) * 2e-6f;
  }
  si->t = t;
  si->time = ray.time;
  si->wo = -glm::normalize(ray.d);
  si->material = prim->material;
  si->area_light = prim->area_light;
  si->medium_interface = prim->media.is_transition() ? &prim->media : nullptr;
  return true;
}

bool Scene::occluded(const Ray& ray) const {
  if (!committed_) throw std::logic_error("Scene::occluded before commit()");
  if (!traceable(ray)) return false;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay r = to_embree(ray, embree_time(ray.time));
  if (RayRecord* rec = record_.load(std::memory_order_relaxed)) {
    std::lock_guard lock(record_lock_);
    rec->shadow.push_back(r);
  }
  rtcOccluded1(root_, &context, &r);
  // Embree marks an occluded ray by setting tfar to -inf.
  return r.tfar < 0.f;
}

void Scene::record_rays(RayRecord* record) {
  std::lock_guard lock(record_lock_);
  record_.store(record);
}

size_t Scene::primitive_count() const {
  size_t n = 0;
  for (const auto& prim : prims_) n += prim.shape->primitive_count();
  for (const auto& [name, group] : groups_) n += group->primitive_count;
  for (const auto& group : moving_groups_) n += group->primitive_count;
  return n;
}

}  // namespace eyetrace
