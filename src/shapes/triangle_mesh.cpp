#include "shapes/triangle_mesh.h"

#include <algorithm>

#include "core/float_error.h"
#include "core/sampling.h"
#include "shapes/hit_filter.h"

namespace eyetrace {

namespace {

// Unit vector along `v` even when |v|^2 would under- or overflow in float; zero if v is zero
// or not finite.
Vec3 robust_normalize(const Vec3& v) {
  float m = std::max(std::abs(v.x), std::max(std::abs(v.y), std::abs(v.z)));
  if (!(m > 0.f) || !std::isfinite(m)) return Vec3(0.f);
  Vec3 s = v / m;
  return s / glm::length(s);
}

// pbrt's default (u, v) for the corners of a triangle without "uv".
constexpr Vec2 kDefaultUV[3] = {Vec2(0.f, 0.f), Vec2(1.f, 0.f), Vec2(1.f, 1.f)};

}  // namespace

TriangleMesh::TriangleMesh(MeshData mesh, const Transform& world_from_object, bool reverse_orientation,
                           const MeshSource& source)
    : flip_normal_(reverse_orientation != world_from_object.swaps_handedness()) {
  validate(mesh, source);
  // pbrt flips given shading normals with ReverseOrientation (not with handedness: the
  // inverse-transpose transform already keeps them on the surface's outer side).
  for (Vec3& n : mesh.normals) {
    n = world_from_object.normal(n);
    if (reverse_orientation) n = -n;
  }
  build(mesh, world_from_object, source);
}

void TriangleMesh::validate(MeshData& mesh, const MeshSource& src) const {
  const ParameterList& params = src.params;
  size_t nv = mesh.positions.size();
  if (nv == 0) params.fail(src.p, src.context + "the mesh has no vertex positions");
  if (mesh.indices.empty()) {
    if (nv != 3)
      params.fail(src.indices, src.context + fmt::format("vertex indices are required unless the mesh has "
                                                         "exactly 3 vertices (it has {})",
                                                         nv));
    mesh.indices = {0, 1, 2};
  }
  if (mesh.indices.size() % 3 != 0)
    params.fail(src.indices,
                src.context + fmt::format("{} vertex indices is not a multiple of 3", mesh.indices.size()));
  for (size_t i = 0; i < mesh.indices.size(); ++i)
    if (mesh.indices[i] < 0 || size_t(mesh.indices[i]) >= nv)
      params.fail(src.indices, src.context + fmt::format("index {} (entry {}) is out of range: there are {} "
                                                         "vertices",
                                                         mesh.indices[i], i, nv));
  if (!mesh.normals.empty() && mesh.normals.size() != nv)
    params.fail(src.n, src.context + fmt::format("{} normals given for {} vertices", mesh.normals.size(), nv));
  if (!mesh.uvs.empty() && mesh.uvs.size() != nv)
    params.fail(src.uv, src.context + fmt::format("{} uv values given for {} vertices", mesh.uvs.size(), nv));
  for (size_t i = 0; i < nv; ++i)
    if (!is_finite(mesh.positions[i])) params.fail(src.p, src.context + fmt::format("vertex {} is not finite", i));
}

void TriangleMesh::build(MeshData& mesh, const Transform& world_from_object, const MeshSource& src) {
  vertex_count_ = mesh.positions.size();
  positions_.reserve(vertex_count_ + 1);
  for (size_t i = 0; i < vertex_count_; ++i) {
    Vec3 p = world_from_object.point(mesh.positions[i]);
    if (!is_finite(p))
      src.params.fail(src.p, src.context + fmt::format("vertex {} is not finite after the object's transform", i));
    positions_.push_back(p);
  }
  positions_.push_back(Vec3(0.f));  // padding for Embree's 16-byte loads (see header)

  indices_.reserve(mesh.indices.size());
  cdf_.reserve(mesh.indices.size() / 3);
  point_error_.reserve(mesh.indices.size() / 3);
  face_normal_.reserve(mesh.indices.size() / 3);
  double total = 0.0;
  for (size_t i = 0; i < mesh.indices.size(); i += 3) {
    const Vec3 &p0 = positions_[mesh.indices[i]], &p1 = positions_[mesh.indices[i + 1]],
               &p2 = positions_[mesh.indices[i + 2]];
    // Degenerate means: no usable normal in float (the same cross product interaction()
    // uses), so such a triangle could only ever produce NaN shading frames.
    const Vec3 n = robust_normalize(glm::cross(p0 - p2, p1 - p2));
    if (n == Vec3(0.f)) {
      ++dropped_;
      continue;
    }
    face_normal_.push_back(n);
    glm::dvec3 e1 = glm::dvec3(p1) - glm::dvec3(p0), e2 = glm::dvec3(p2) - glm::dvec3(p0);
    total += 0.5 * glm::length(glm::cross(e1, e2));
    cdf_.push_back(total);
    point_error_.push_back(triangle_error(Corner{{p0, p1, p2}, {}}));
    for (int k = 0; k < 3; ++k) {
      indices_.push_back(uint32_t(mesh.indices[i + k]));
      bounds_.extend(positions_[mesh.indices[i + k]]);
    }
  }
  if (dropped_ > 0)
    warn(src.params.loc(), src.context + fmt::format("dropped {} degenerate (zero-area) triangle(s) of {}", dropped_,
                                                     mesh.indices.size() / 3));
  if (indices_.empty() || !(total > 0.0) || !std::isfinite(total))
    src.params.fail(src.p, src.context + "the mesh has no triangle of nonzero, finite area");
  for (double& c : cdf_) c /= total;
  cdf_.back() = 1.0;
  area_ = float(total);
  normals_ = std::move(mesh.normals);
  uvs_ = std::move(mesh.uvs);
}

unsigned TriangleMesh::attach(RTCDevice device, RTCScene scene) const {
  RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  // Shared buffers: Embree reads our arrays directly, no second copy of a large mesh.
  rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, positions_.data(), 0, sizeof(Vec3),
                             vertex_count_);
  rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, indices_.data(), 0, 3 * sizeof(uint32_t),
                             indices_.size() / 3);
  if (!alpha_.opaque()) {
    rtcSetGeometryUserData(geom, const_cast<TriangleMesh*>(this));
    rtcSetGeometryIntersectFilterFunction(geom, alpha_filter);
    rtcSetGeometryOccludedFilterFunction(geom, alpha_filter);
  }
  rtcCommitGeometry(geom);
  unsigned id = rtcAttachGeometry(scene, geom);
  rtcReleaseGeometry(geom);
  return id;
}

bool TriangleMesh::alpha_passes(unsigned tri, float b1, float b2, const Vec3& o, const Vec3& d, float t) const {
  if (alpha_.opaque()) return true;
  const Corner c = corners(tri);
  const float b0 = 1.f - b1 - b2;
  TextureEvalContext ctx;
  ctx.p = o + t * d;
  ctx.uv = b0 * c.uv[0] + b1 * c.uv[1] + b2 * c.uv[2];
  ctx.n = face_normal_[tri];
  return alpha_.passes(ctx, o, d);
}

// Every candidate hit of a mesh with alpha (shapes/hit_filter.h).
void TriangleMesh::alpha_filter(const RTCFilterFunctionNArguments* args) {
  const auto* mesh = static_cast<const TriangleMesh*>(args->geometryUserPtr);
  filter_hits(args, [mesh](unsigned tri, float b1, float b2, const Vec3& o, const Vec3& d, float t) {
    return mesh->alpha_passes(tri, b1, b2, o, d, t);
  });
}

TriangleMesh::Corner TriangleMesh::corners(unsigned tri) const {
  Corner c;
  for (int k = 0; k < 3; ++k) {
    uint32_t v = indices_[3 * tri + k];
    c.p[k] = positions_[v];
    c.uv[k] = uvs_.empty() ? kDefaultUV[k] : uvs_[v];
  }
  return c;
}

Vec3 TriangleMesh::triangle_error(const Corner& c) {
  // The exact point with Embree's barycentrics b1, b2 (and b0 = 1 - b1 - b2 exactly) lies
  // on the (world-space float) triangle whatever Embree's own rounding was. Ours differs from
  // it twice: b0 p0 + b1 p1 + b2 p2 is three products and two sums per axis, within gamma(7)
  // times sum |b_i p_i| (pbrt-v4, PBR 4th ed. 6.8.5); and b0 computed as 1 - b1 - b2 in float
  // is off by up to gamma(2) (1 + b1 + b2) <= 4u absolutely (not relatively: b0 may be tiny),
  // which moves the point by at most gamma(5) |p0|. With b_i >= 0 summing to 1 (within 2u),
  // sum |b_i p_i| <= (1 + gamma(2)) max |p_i| per axis, and gamma(7) (1 + gamma(2)) + gamma(5)
  // <= gamma(13): one bound for every point of the triangle (area samples, which compute b2
  // instead of b0, included), computed at load, so a hit costs one load.
  Vec3 corner_max = glm::max(glm::abs(c.p[0]), glm::max(glm::abs(c.p[1]), glm::abs(c.p[2])));
  return gamma(13) * corner_max + Vec3(embree_plane_error(c));
}

float TriangleMesh::embree_plane_error(const Corner& c) {
  // pbrt's own triangle test accepts only a conservatively positive t, so its offset need
  // only clear the error box of p. Embree accepts any computed t >= tnear = 0, so a spawned
  // origin must also lie farther from the plane than Embree's own rounding can misjudge.
  // Embree decides the side from T = dot(Ng, v0 - o) with Ng = cross(v0 - v1, v2 - v0) in
  // float: about eight chained roundings, each relative to the terms' magnitudes, so |T| is
  // uncertain by gamma(8) |e1| |e2| |v0 - o| (times sqrt(3) for the sum over axes). As a
  // distance that is T / |Ng|: gamma(8) sqrt(3) |v0 - o| |e1| |e2| / |e1 x e2|; |v0 - o| is
  // at most the longest edge plus the offset, and gamma(16) covers the sqrt(3), the offset
  // and the neighbouring triangles of similar shape a ray may meet near the edge.
  Vec3 e1 = c.p[0] - c.p[1], e2 = c.p[2] - c.p[0], e3 = c.p[1] - c.p[2];
  Vec3 n = glm::cross(e1, e2);
  float cross2 = glm::dot(n, n);
  if (!(cross2 > 0.f)) return 0.f;  // degenerate: Embree reports no hit on it
  float l1_2 = glm::dot(e1, e1), l2_2 = glm::dot(e2, e2), l3_2 = glm::dot(e3, e3);
  float longest2 = std::max(l1_2, std::max(l2_2, l3_2));
  return gamma(16) * std::sqrt(longest2 * (l1_2 / cross2) * l2_2);
}

void TriangleMesh::normals_at(unsigned tri, float b0, float b1, float b2, Vec3* n, Vec3* ns) const {
  // pbrt: n along cross(p0 - p2, p1 - p2) of the world-space corners, flipped when
  // ReverseOrientation XOR the transform swaps handedness; given shading normals instead
  // decide the side the geometric normal faces.
  // Computed once per triangle at build time from the same world-space corners (the same
  // bits; it was 2 % of a figure-scene render, recomputed at every hit).
  *n = face_normal_[tri];
  if (normals_.empty()) {
    if (flip_normal_) *n = -*n;
    *ns = *n;
    return;
  }
  const uint32_t* v = &indices_[3 * tri];
  Vec3 s = robust_normalize(b0 * normals_[v[0]] + b1 * normals_[v[1]] + b2 * normals_[v[2]]);
  if (s == Vec3(0.f)) {
    if (flip_normal_) *n = -*n;
    *ns = *n;
    return;
  }
  if (glm::dot(*n, s) < 0.f) *n = -*n;
  *ns = s;
}

SurfaceInteraction TriangleMesh::interaction(const Ray& ray, float t, unsigned prim_id, Vec2 uv, Vec3) const {
  Corner c = corners(prim_id);
  // Embree's barycentrics: u weights vertex 1, v weights vertex 2.
  float b1 = uv.x, b2 = uv.y, b0 = 1.f - b1 - b2;
  SurfaceInteraction si;
  // The barycentric point lies on the triangle's plane to float rounding, which keeps the
  // spawned-ray offset small; ray.at(t) can be off the plane by |o| * eps.
  si.p = b0 * c.p[0] + b1 * c.p[1] + b2 * c.p[2];
  si.p_error = point_error_[prim_id];
  si.t = t;
  si.uv = b0 * c.uv[0] + b1 * c.uv[1] + b2 * c.uv[2];
  normals_at(prim_id, b0, b1, b2, &si.n, &si.ns);

  // dp/du, dp/dv from the uv parameterisation (pbrt's 2x2 solve); a degenerate uv mapping
  // falls back to an arbitrary frame around n.
  Vec2 duv02 = c.uv[0] - c.uv[2], duv12 = c.uv[1] - c.uv[2];
  Vec3 dp02 = c.p[0] - c.p[2], dp12 = c.p[1] - c.p[2];
  float det = duv02.x * duv12.y - duv02.y * duv12.x;
  bool ok = std::abs(det) > 1e-12f;
  if (ok) {
    float inv = 1.f / det;
    si.dpdu = (duv12.y * dp02 - duv02.y * dp12) * inv;
    si.dpdv = (duv02.x * dp12 - duv12.x * dp02) * inv;
    Vec3 cr = glm::cross(si.dpdu, si.dpdv);
    ok = is_finite(cr) && glm::dot(cr, cr) > 0.f;
  }
  if (!ok) coordinate_system(si.n, &si.dpdu, &si.dpdv);
  si.wo = -glm::normalize(ray.d);
  si.time = ray.time;
  return si;
}

ShapeSample TriangleMesh::sample_area(Vec2 u) const {
  // Choose a triangle with probability area / total, then reuse u.x within its CDF slot.
  size_t tri = size_t(std::upper_bound(cdf_.begin(), cdf_.end(), double(u.x)) - cdf_.begin());
  tri = std::min(tri, cdf_.size() - 1);
  double lo = tri == 0 ? 0.0 : cdf_[tri - 1];
  double width = cdf_[tri] - lo;
  float ux = width > 0.0 ? float((double(u.x) - lo) / width) : 0.f;
  ux = std::clamp(ux, 0.f, kOneMinusEpsilon);

  Vec2 b = sample_uniform_triangle(Vec2(ux, u.y));
  float b0 = b.x, b1 = b.y, b2 = std::max(0.f, 1.f - b0 - b1);
  Corner c = corners(unsigned(tri));
  ShapeSample s;
  s.p = b0 * c.p[0] + b1 * c.p[1] + b2 * c.p[2];
  s.p_error = point_error_[tri];
  s.uv = b0 * c.uv[0] + b1 * c.uv[1] + b2 * c.uv[2];
  Vec3 ns;
  normals_at(unsigned(tri), b0, b1, b2, &s.n, &ns);
  s.pdf_area = 1.f / area_;
  return s;
}

const PluginSpec& trianglemesh_shape_spec() {
  static const PluginSpec spec{
      "Shape",
      "a triangle mesh given in the scene",
      "Tangents `S` are ignored.",
      {param::point3s("P").shown_default("required").describe("vertex positions"),
       param::integers("indices").describe("3 per triangle (optional for exactly 3 vertices)"),
       param::normals("N").describe("per-vertex shading normals"), param::point2s("uv").describe("per-vertex (u, v)"),
       param::integers("faceIndices").describe("one per triangle (checked, otherwise unused)"),
       param::vector3s("S").describe("read and ignored, with a warning"), alpha_param()}};
  return spec;
}

std::unique_ptr<TriangleMesh> make_mesh_shape(MeshData mesh, const ShapeContext& ctx, const PluginParams& params,
                                              const MeshSource& source) {
  auto tri = std::make_unique<TriangleMesh>(std::move(mesh), ctx.world_from_object, ctx.reverse_orientation, source);
  tri->set_alpha(read_alpha(ctx, params));
  return tri;
}

std::vector<std::unique_ptr<Shape>> create_trianglemesh_shapes(const ShapeContext& ctx) {
  const PluginParams params(ctx.params, trianglemesh_shape_spec(), "trianglemesh");
  MeshData mesh;
  mesh.positions = params.get_point3s("P");
  mesh.indices = params.get_ints("indices");
  mesh.normals = params.get_normals("N");
  mesh.uvs = params.get_point2s("uv");
  if (params.has("S")) params.warn_param("S", "tangents are ignored; shading frames come from \"N\" and \"uv\"");
  std::vector<int> face_indices = params.get_ints("faceIndices");
  std::vector<std::unique_ptr<Shape>> shapes;
  auto tri = make_mesh_shape(std::move(mesh), ctx, params, MeshSource{ctx.params});
  if (!face_indices.empty() && face_indices.size() != tri->primitive_count() + size_t(tri->dropped_triangles()))
    params.fail("faceIndices", fmt::format("{} face indices given for {} triangles", face_indices.size(),
                                           tri->primitive_count() + tri->dropped_triangles()));
  shapes.push_back(std::move(tri));
  return shapes;
}

}  // namespace eyetrace
