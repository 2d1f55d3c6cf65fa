#include "shapes/analytic_shape.h"

#include <algorithm>
#include <glm/gtc/matrix_inverse.hpp>

#include "core/float_error.h"

namespace eyetrace {

namespace {

// Embree callbacks: one virtual call per candidate, which only analytic shapes pay.
void bounds_callback(const RTCBoundsFunctionArguments* args) {
  const auto* shape = static_cast<const AnalyticShape*>(args->geometryUserPtr);
  Bounds3 b = shape->bounds();
  RTCBounds* out = args->bounds_o;
  out->lower_x = b.lo.x, out->lower_y = b.lo.y, out->lower_z = b.lo.z;
  out->upper_x = b.hi.x, out->upper_y = b.hi.y, out->upper_z = b.hi.z;
}

void intersect_callback(const RTCIntersectFunctionNArguments* args) {
  const auto* shape = static_cast<const AnalyticShape*>(args->geometryUserPtr);
  unsigned n = args->N;
  RTCRayN* rays = RTCRayHitN_RayN(args->rayhit, n);
  RTCHitN* hits = RTCRayHitN_HitN(args->rayhit, n);
  for (unsigned i = 0; i < n; ++i) {
    if (args->valid[i] != -1) continue;
    Vec3 o(RTCRayN_org_x(rays, n, i), RTCRayN_org_y(rays, n, i), RTCRayN_org_z(rays, n, i));
    Vec3 d(RTCRayN_dir_x(rays, n, i), RTCRayN_dir_y(rays, n, i), RTCRayN_dir_z(rays, n, i));
    float& tfar = RTCRayN_tfar(rays, n, i);
    std::optional<double> t = shape->hit(o, d, RTCRayN_tnear(rays, n, i), tfar);
    if (!t) continue;
    // Rounding t < tfar to float cannot pass tfar, which is itself a float.
    tfar = float(*t);
    // interaction() recomputes everything from t; Ng is only Embree's bookkeeping.
    RTCHitN_Ng_x(hits, n, i) = 0.f;
    RTCHitN_Ng_y(hits, n, i) = 0.f;
    RTCHitN_Ng_z(hits, n, i) = 1.f;
    RTCHitN_u(hits, n, i) = 0.f;
    RTCHitN_v(hits, n, i) = 0.f;
    RTCHitN_primID(hits, n, i) = args->primID;
    RTCHitN_geomID(hits, n, i) = args->geomID;
    RTCHitN_instID(hits, n, i, 0) = args->context->instID[0];
  }
}

void occluded_callback(const RTCOccludedFunctionNArguments* args) {
  const auto* shape = static_cast<const AnalyticShape*>(args->geometryUserPtr);
  unsigned n = args->N;
  for (unsigned i = 0; i < n; ++i) {
    if (args->valid[i] != -1) continue;
    RTCRayN* rays = args->ray;
    Vec3 o(RTCRayN_org_x(rays, n, i), RTCRayN_org_y(rays, n, i), RTCRayN_org_z(rays, n, i));
    Vec3 d(RTCRayN_dir_x(rays, n, i), RTCRayN_dir_y(rays, n, i), RTCRayN_dir_z(rays, n, i));
    float& tfar = RTCRayN_tfar(rays, n, i);
    if (shape->hit(o, d, RTCRayN_tnear(rays, n, i), tfar)) tfar = -kInfinity;
  }
}

}  // namespace

AnalyticShape::AnalyticShape(const Transform& world_from_object, bool reverse_orientation)
    : world_from_object_(world_from_object.matrix()), reverse_orientation_(reverse_orientation) {
  // The float inverse stored in Transform loses bits; invert again in double.
  object_from_world_ = glm::inverse(world_from_object_);
  glm::dmat3 linear(world_from_object_);
  normal_from_object_ = glm::inverseTranspose(linear);
  double det = std::abs(glm::determinant(linear));
  double s2 = std::pow(det, 2.0 / 3.0);
  area_scale_ = s2;
  glm::dmat3 mtm = glm::transpose(linear) * linear;  // s^2 I for a similarity
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r)
      if (std::abs(mtm[c][r] - (c == r ? s2 : 0.0)) > 1e-5 * s2) is_similarity_ = false;
}

double AnalyticShape::plane_area_scale() const {
  // dA' = |det M| |M^-T n| dA for a plane with unit normal n (here +z).
  glm::dmat3 linear(world_from_object_);
  return std::abs(glm::determinant(linear)) * glm::length(normal_from_object_ * glm::dvec3(0, 0, 1));
}

std::optional<double> AnalyticShape::hit(const Vec3& o, const Vec3& d, double tmin, double tmax) const {
  const DRay r = to_object(o, d);
  // A cut-out crossing is skipped and the next one looked for beyond it: a quadric has at most
  // two, so the loop's bound is only a guard.
  for (int crossing = 0; crossing < 4; ++crossing) {
    const std::optional<double> t = hit_object(r, tmin, tmax);
    if (!t || alpha_.opaque()) return t;
    SurfaceInteraction si;
    surface_at(r.o + *t * r.d, &si);
    if (alpha_.passes(TextureEvalContext(si), o, d)) return t;
    tmin = *t;
  }
  return std::nullopt;
}

unsigned AnalyticShape::attach(RTCDevice device, RTCScene scene) const {
  RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
  rtcSetGeometryUserPrimitiveCount(geom, 1);
  rtcSetGeometryUserData(geom, const_cast<AnalyticShape*>(this));
  rtcSetGeometryBoundsFunction(geom, bounds_callback, nullptr);
  rtcSetGeometryIntersectFunction(geom, intersect_callback);
  rtcSetGeometryOccludedFunction(geom, occluded_callback);
  rtcCommitGeometry(geom);
  unsigned id = rtcAttachGeometry(scene, geom);
  rtcReleaseGeometry(geom);
  return id;
}

Bounds3 AnalyticShape::bounds() const {
  glm::dvec3 lo, hi;
  object_bounds(&lo, &hi);
  glm::dvec3 wlo(std::numeric_limits<double>::infinity()), whi(-std::numeric_limits<double>::infinity());
  for (int corner = 0; corner < 8; ++corner) {
    glm::dvec3 p((corner & 1) ? hi.x : lo.x, (corner & 2) ? hi.y : lo.y, (corner & 4) ? hi.z : lo.z);
    glm::dvec3 w(world_from_object_ * glm::dvec4(p, 1.0));
    wlo = glm::min(wlo, w);
    whi = glm::max(whi, w);
  }
  // Round outwards so the float box contains the double one.
  Bounds3 b;
  for (int k = 0; k < 3; ++k) {
    b.lo[k] = std::nextafter(float(wlo[k]), -kInfinity);
    b.hi[k] = std::nextafter(float(whi[k]), kInfinity);
  }
  return b;
}

DRay AnalyticShape::to_object(const Vec3& o, const Vec3& d) const {
  DRay r;
  r.o = glm::dvec3(object_from_world_ * glm::dvec4(glm::dvec3(o), 1.0));
  r.d = glm::dvec3(object_from_world_ * glm::dvec4(glm::dvec3(d), 0.0));
  return r;
}

Vec3 AnalyticShape::point_to_world(const glm::dvec3& p) const { return Vec3(world_from_object_ * glm::dvec4(p, 1.0)); }

Vec3 AnalyticShape::vector_to_world(const glm::dvec3& v) const { return Vec3(world_from_object_ * glm::dvec4(v, 0.0)); }

Vec3 AnalyticShape::normal_to_world(const glm::dvec3& n) const {
  glm::dvec3 w = glm::normalize(normal_from_object_ * n);
  return Vec3(reverse_orientation_ ? -w : w);
}

SurfaceInteraction AnalyticShape::interaction(const Ray& ray, float t, unsigned, Vec2, Vec3) const {
  DRay r = to_object(ray.o, ray.d);
  SurfaceInteraction si;
  surface_at(r.o + double(t) * r.d, &si);
  finish(ray, t, &si);
  return si;
}

Vec3 AnalyticShape::point_error(const glm::dvec3& p, double p_rel_error) const {
  // Double rounding of n chained operations: gamma_d(n) = n u / (1 - n u), u = 2^-53.
  constexpr double kUnitD = std::numeric_limits<double>::epsilon() * 0.5;
  constexpr double kGammaD3 = 3.0 * kUnitD / (1.0 - 3.0 * kUnitD);
  const glm::dmat4& m = world_from_object_;
  glm::dvec3 pw(m * glm::dvec4(p, 1.0));
  Vec3 err;
  for (int r = 0; r < 3; ++r) {
    // Each world coordinate is a sum of four double products: gamma_d(3) times the terms'
    // magnitudes (pbrt's Transform rule); the object error goes through |M| (times 1 + gamma_d(3)).
    double terms = std::abs(m[0][r] * p.x) + std::abs(m[1][r] * p.y) + std::abs(m[2][r] * p.z) + std::abs(m[3][r]);
    double carried = (std::abs(m[0][r] * p.x) + std::abs(m[1][r] * p.y) + std::abs(m[2][r] * p.z)) * p_rel_error;
    // Rounding the double result to float adds at most half an ulp: kMachineEpsilon |pw|.
    double e = kGammaD3 * terms + (1.0 + kGammaD3) * carried + double(kMachineEpsilon) * std::abs(pw[r]);
    // The sums above are themselves rounded (relative 1e-15): a factor of 1 + 1e-6 and the
    // step up to the next float keep the float bound above the exact one.
    err[r] = next_float_up(float(e * (1.0 + 1e-6)));
  }
  return err;
}

void AnalyticShape::set_surface(SurfaceInteraction* si, const glm::dvec3& p, const glm::dvec3& n, double u, double v,
                                const glm::dvec3& dpdu, const glm::dvec3& dpdv, double p_rel_error) const {
  si->p = point_to_world(p);
  si->p_error = point_error(p, p_rel_error);
  si->n = normal_to_world(n);
  si->uv = Vec2(float(std::clamp(u, 0.0, 1.0)), float(std::clamp(v, 0.0, 1.0)));
  si->dpdu = vector_to_world(dpdu);
  si->dpdv = vector_to_world(dpdv);
}

void AnalyticShape::finish(const Ray& ray, float t, SurfaceInteraction* si) const {
  Vec3 c = glm::cross(si->dpdu, si->dpdv);
  if (!(glm::dot(c, c) > 0.f) || !std::isfinite(glm::dot(c, c))) coordinate_system(si->n, &si->dpdu, &si->dpdv);
  si->ns = si->n;
  si->t = t;
  si->wo = -glm::normalize(ray.d);
  si->time = ray.time;
}

ShapeSample AnalyticShape::area_sample_at(const glm::dvec3& p) const {
  SurfaceInteraction si;
  surface_at(p, &si);
  ShapeSample s;
  s.p = si.p;
  s.p_error = si.p_error;
  s.n = si.n;
  s.uv = si.uv;
  s.pdf_area = 1.f / area();
  return s;
}

}  // namespace eyetrace
