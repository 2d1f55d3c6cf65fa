#include "shapes/curve.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/float_error.h"
#include "shapes/hit_filter.h"

namespace eyetrace {

namespace {

// Embree's flat curves are at most this many chords per primitive (rtcSetGeometryTessellationRate
// clamps to 16).
constexpr int kMaxChords = 16;

Vec3 lerp3(float t, const Vec3& a, const Vec3& b) { return (1.f - t) * a + t * b; }

std::pair<BezierSegment, BezierSegment> split_half(const BezierSegment& c) {
  const Vec3 a = 0.5f * (c[0] + c[1]), b = 0.5f * (c[1] + c[2]), d = 0.5f * (c[2] + c[3]);
  const Vec3 ab = 0.5f * (a + b), bd = 0.5f * (b + d), m = 0.5f * (ab + bd);
  return {BezierSegment{c[0], a, ab, m}, BezierSegment{m, bd, d, c[3]}};
}

// Chords a polyline needs to stay within eps of the cubic: a chord over a parameter interval h
// strays at most h^2 / 8 max |c''|, and |c''| <= 6 max |second difference of the points|.
int chords_needed(const BezierSegment& c, float eps) {
  float l0 = 0.f;
  for (int i = 0; i < 2; ++i) l0 = std::max(l0, glm::length(c[i] - 2.f * c[i + 1] + c[i + 2]));
  if (!(l0 > 0.f)) return 1;
  const float n = std::ceil(std::sqrt(6.f * l0 / (8.f * eps)));
  return n < 1e6f ? std::max(1, int(n)) : 1000000;
}

// Unit vector at fraction t of the great-circle arc from unit a to unit b (pbrt-v4's ribbon normal).
Vec3 slerp(float t, const Vec3& a, const Vec3& b) {
  const float angle = std::acos(std::clamp(glm::dot(a, b), -1.f, 1.f));
  if (angle < 1e-4f) return glm::normalize(lerp3(t, a, b));
  const float inv_sin = 1.f / std::sin(angle);
  return std::sin((1.f - t) * angle) * inv_sin * a + std::sin(t * angle) * inv_sin * b;
}

// x turned by `angle` (radians, right-handed) about unit axis a (Rodrigues).
Vec3 rotate_about(const Vec3& x, const Vec3& a, float angle) {
  const float c = std::cos(angle), s = std::sin(angle);
  return x * c + glm::cross(a, x) * s + a * glm::dot(a, x) * (1.f - c);
}

Vec3 safe_normalize(const Vec3& v, const Vec3& fallback) {
  const float l = glm::length(v);
  return l > 0.f && std::isfinite(l) ? v / l : fallback;
}

}  // namespace

Curve::Curve(const std::vector<CurveSegment>& segments, CurveType type, const Transform& world_from_object,
             bool reverse_orientation)
    : type_(type),
      handedness_(world_from_object.swaps_handedness() ? -1.f : 1.f),
      orientation_(reverse_orientation ? -1.f : 1.f) {
  // Bezier curves are affine invariant: the world curve's control points are the transformed
  // ones. pbrt-v4 measures width in object space; here it is scaled by the transform's mean
  // linear scale (exact for similarities; the factory warns otherwise).
  const float scale = std::cbrt(std::abs(glm::determinant(glm::mat3(world_from_object.matrix()))));
  for (const CurveSegment& s : segments) {
    CurveSegment w;
    for (int k = 0; k < 4; ++k) w.cp[k] = world_from_object.point(s.cp[k]);
    w.width0 = s.width0 * scale;
    w.width1 = s.width1 * scale;
    if (type == CurveType::Ribbon) {
      w.n0 = safe_normalize(world_from_object.normal(s.n0), Vec3(0, 0, 1));
      w.n1 = safe_normalize(world_from_object.normal(s.n1), Vec3(0, 0, 1));
    }
    segments_.push_back(w);
  }
  build_pieces();
}

namespace {

// A piece of a segment, from parameter u0 to u1, with its own control points.
struct SubCurve {
  BezierSegment cp;
  float u0, u1;
};

// The segment split in halves until each piece needs at most kMaxChords chords within eps
// (halving the parameter interval quarters the second differences); *rate becomes the most
// chords any piece needs.
std::vector<SubCurve> split_for_chords(const BezierSegment& cp, float eps, int* rate) {
  std::vector<SubCurve> stack{{cp, 0.f, 1.f}}, done;
  while (!stack.empty()) {
    const SubCurve t = stack.back();
    stack.pop_back();
    const int n = chords_needed(t.cp, eps);
    if (n <= kMaxChords || t.u1 - t.u0 < 1.f / 1024.f) {
      *rate = std::max(*rate, std::min(n, kMaxChords));
      done.push_back(t);
      continue;
    }
    auto [l, r] = split_half(t.cp);
    const float um = 0.5f * (t.u0 + t.u1);
    stack.push_back({r, um, t.u1});
    stack.push_back({l, t.u0, um});
  }
  return done;
}

// Integral of the width (2 r, linear from r0 to r1) times |dp/du| over a piece: Simpson's rule
// on 8 intervals.
double band_area(const BezierSegment& cp, float r0, float r1) {
  constexpr int kN = 8;
  double area = 0.0;
  for (int i = 0; i <= kN; ++i) {
    const float u = float(i) / kN;
    const double weight = i == 0 || i == kN ? 1.0 : (i % 2 ? 4.0 : 2.0);
    area += weight * 2.0 * (r0 + u * (r1 - r0)) * glm::length(bezier_derivative(cp, u)) / (3.0 * kN);
  }
  return area;
}

}  // namespace

void Curve::build_pieces() {
  int rate = 1;
  double area = 0.0;
  for (unsigned si = 0; si < segments_.size(); ++si) {
    const CurveSegment& s = segments_[si];
    // Chords within a hundredth of the wider end's width of the curve: pbrt-v4 refines to a
    // twentieth but then tests the true cubic; at a twentieth, chords moved the silhouettes and
    // shadow edges by a measurable amount against pbrt-v4 (7 standard errors at 1024 spp).
    const float eps = std::max(s.width0, s.width1) * 0.01f;
    for (const SubCurve& t : split_for_chords(s.cp, eps, &rate)) {
      const float r0 = 0.5f * (s.width0 + t.u0 * (s.width1 - s.width0));
      const float r1 = 0.5f * (s.width0 + t.u1 * (s.width1 - s.width0));
      indices_.push_back(unsigned(vertices_.size()));
      // A radius linear in u is, in Bezier form, control radii at thirds.
      for (int k = 0; k < 4; ++k) {
        vertices_.push_back(Vec4(t.cp[k], r0 + (r1 - r0) * float(k) / 3.f));
        bounds_.extend(t.cp[k] - Vec3(std::max(r0, r1)));
        bounds_.extend(t.cp[k] + Vec3(std::max(r0, r1)));
      }
      pieces_.push_back(Piece{si, t.u0, t.u1});
      area += band_area(t.cp, r0, r1);
    }
  }
  area_ = float(area);
  tessellation_ = rate;
}

Vec3 Curve::ribbon_normal(const CurveSegment& s, float u) const { return slerp(u, s.n0, s.n1); }

unsigned Curve::attach(RTCDevice device, RTCScene scene) const {
  // Every type is Embree's flat curve, the band facing the ray at the full width; a ribbon's
  // narrower band (width |N . d|) is cut from it in the filter.
  RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_FLAT_BEZIER_CURVE);
  rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, vertices_.data(), 0, sizeof(Vec4),
                             vertices_.size());
  rtcSetSharedGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT, indices_.data(), 0, sizeof(uint32_t),
                             indices_.size());
  rtcSetGeometryTessellationRate(geom, float(tessellation_));
  if (!alpha_.opaque() || type_ == CurveType::Ribbon) {
    rtcSetGeometryUserData(geom, const_cast<Curve*>(this));
    rtcSetGeometryIntersectFilterFunction(geom, filter);
    rtcSetGeometryOccludedFilterFunction(geom, filter);
  }
  rtcCommitGeometry(geom);
  unsigned id = rtcAttachGeometry(scene, geom);
  rtcReleaseGeometry(geom);
  return id;
}

Curve::Local Curve::local_at(unsigned piece, float embree_u, const Vec3& p, const Vec3& d) const {
  const Piece& pc = pieces_[piece];
  const CurveSegment& s = segments_[pc.segment];
  Local l;
  const float u = std::clamp(pc.u0 + std::clamp(embree_u, 0.f, 1.f) * (pc.u1 - pc.u0), 0.f, 1.f);
  const Vec3 c = bezier_point(s.cp, u);
  // A cusp (zero derivative) falls back to the chord, as the tangent must be defined.
  l.dpdu = bezier_derivative(s.cp, u);
  if (!(glm::dot(l.dpdu, l.dpdu) > 0.f)) l.dpdu = s.cp[3] - s.cp[0];
  const Vec3 tangent = safe_normalize(l.dpdu, Vec3(1, 0, 0));
  l.width = s.width0 + u * (s.width1 - s.width0);
  const Vec3 dn = safe_normalize(d, Vec3(0, 0, 1));
  const Vec3 q = p - c;
  // The band faces the ray (for every type, as pbrt-v4 intersects them): across it is d x T
  // (pbrt-v4 works in object space, hence the handedness), and v comes from the distance to
  // the centre line perpendicular to the ray, signed by the side (pbrt-v4's edge function).
  Vec3 b0, b1;
  coordinate_system(tangent, &b0, &b1);
  Vec3 across = handedness_ * safe_normalize(glm::cross(dn, tangent), b0);
  const Vec3 q_perp = q - dn * glm::dot(q, dn);
  const float dist = glm::length(q_perp);
  // A ribbon is as wide as the ray sees it: width |N . d| (pbrt-v4's hitWidth).
  Vec3 nr(0.f);
  if (type_ == CurveType::Ribbon) {
    nr = ribbon_normal(s, u);
    l.width *= std::abs(glm::dot(nr, dn));
  }
  l.inside = dist <= 0.5f * l.width;
  float v = l.width > 0.f ? 0.5f + (glm::dot(q, across) >= 0.f ? dist : -dist) / l.width : 0.5f;
  v = std::clamp(v, 0.f, 1.f);
  // pbrt-v4: a ribbon's dp/dv lies in the ribbon, N x T (object space); the others' across.
  if (type_ == CurveType::Ribbon) across = handedness_ * safe_normalize(glm::cross(nr, tangent), across);
  l.dpdv = across * l.width;
  if (type_ == CurveType::Cylinder) {
    // pbrt-v4: dp/dv turned by -theta about dp/du (object space), theta from -90 to 90 degrees
    // across; a mirroring transform reverses the sense of the turn in world space.
    const float theta = radians(-90.f + 180.f * v);
    l.dpdv = rotate_about(l.dpdv, tangent, -theta * handedness_);
  }
  // n = dp/du x dp/dv, transformed as pbrt-v4 does (see analytic_shape.h: in world space only
  // ReverseOrientation flips it).
  l.n = orientation_ * safe_normalize(glm::cross(l.dpdu, l.dpdv), -dn);
  l.uv = Vec2(u, v);
  return l;
}

SurfaceInteraction Curve::interaction(const Ray& ray, float t, unsigned prim_id, Vec2 uv, Vec3) const {
  SurfaceInteraction si;
  si.p = ray.o + t * ray.d;
  const Local l = local_at(prim_id, uv.x, si.p, ray.d);
  si.uv = l.uv;
  si.n = si.ns = l.n;
  si.dpdu = l.dpdu;
  si.dpdv = l.dpdv;
  // pbrt-v4's error box for curves: the width at the hit (a band facing the ray has no fixed
  // surface to offset from; a ray spawned a width away cannot meet its own band again at
  // the spawn point), plus the rounding of o + t d.
  si.p_error = Vec3(l.width) + gamma(8) * (glm::abs(ray.o) + glm::abs(t * ray.d));
  si.t = t;
  si.wo = -glm::normalize(ray.d);
  si.time = ray.time;
  return si;
}

ShapeSample Curve::sample_area(Vec2) const {
  throw std::logic_error("Curve::sample_area: curves cannot be area lights (the scene builder refuses them)");
}

const char* Curve::emitter_refusal() const {
  return "pbrt-v4 does not sample curves (Curve::Sample is not implemented there), and a band that faces each ray "
         "has no fixed surface to emit from";
}

bool Curve::passes(unsigned piece, float u, const Vec3& o, const Vec3& d, float t) const {
  if (alpha_.opaque() && type_ != CurveType::Ribbon) return true;
  TextureEvalContext ctx;
  ctx.p = o + t * d;
  const Local l = local_at(piece, u, ctx.p, d);
  if (!l.inside) return false;
  ctx.uv = l.uv;
  ctx.n = l.n;
  return alpha_.passes(ctx, o, d);
}

// Every candidate hit of a ribbon or a curve with alpha (shapes/hit_filter.h).
void Curve::filter(const RTCFilterFunctionNArguments* args) {
  const auto* curve = static_cast<const Curve*>(args->geometryUserPtr);
  filter_hits(args, [curve](unsigned piece, float u, float, const Vec3& o, const Vec3& d, float t) {
    return curve->passes(piece, u, o, d, t);
  });
}

const PluginSpec& curve_shape_spec() {
  static const PluginSpec spec{
      "Shape",
      "a curve of cubic (or quadratic) Bezier or B-spline segments swept to a band: hair, fur, grass",
      "\"splitdepth\" is read and has no effect (Embree builds its own hierarchy); area lights on curves are "
      "refused (pbrt-v4 aborts on them); a non-uniform scale scales the width by its mean",
      {param::point3s("P").shown_default("required").describe("control points"),
       param::string("basis", "bezier").in({"bezier", "bspline"}).describe("how P makes segments"),
       param::integer("degree", 3).describe("2 or 3"),
       param::string("type", "flat")
           .in({"flat", "cylinder", "ribbon"})
           .describe(
               "flat: band facing the ray; cylinder: that band, normal bent across it; ribbon: band oriented by N"),
       param::normals("N").describe("ribbon normals, one per segment end (segments + 1)"),
       param::real("width", 1).above(0).with_unit("scene units").describe("width at both ends"),
       param::real("width0").above(0).with_unit("scene units").shown_default("width").describe("width at the start"),
       param::real("width1").above(0).with_unit("scene units").shown_default("width").describe("width at the end"),
       param::integer("splitdepth", 3).at_least(0).describe("pbrt-v4's BVH splitting: read, no effect"),
       alpha_param()}};
  return spec;
}

namespace {

CurveBasis read_basis(const PluginParams& params) {
  return params.get_string("basis") == "bspline" ? CurveBasis::BSpline : CurveBasis::Bezier;
}

CurveType read_type(const PluginParams& params) {
  const std::string t = params.get_string("type");
  return t == "ribbon" ? CurveType::Ribbon : t == "cylinder" ? CurveType::Cylinder : CurveType::Flat;
}

}  // namespace

std::vector<std::unique_ptr<Shape>> create_curve_shapes(const ShapeContext& ctx) {
  const PluginParams params(ctx.params, curve_shape_spec(), "curve");
  const std::vector<Vec3> points = params.get_point3s("P");
  const int degree = params.get_int("degree");
  if (degree != 2 && degree != 3)
    params.fail("degree", fmt::format("degree {} is not supported: curves are of degree 2 or 3", degree));
  const CurveBasis basis = read_basis(params);
  const std::optional<int> segments = curve_segment_count(points.size(), basis, degree);
  if (points.empty()) params.fail("P", "the curve has no control points");
  if (!segments)
    params.fail("P", fmt::format("{} control points: {}", points.size(), curve_point_count_rule(basis, degree)));
  for (size_t i = 0; i < points.size(); ++i)
    if (!std::isfinite(points[i].x) || !std::isfinite(points[i].y) || !std::isfinite(points[i].z))
      params.fail("P", fmt::format("control point {} is not finite", i));
  const float width = params.get_float("width");
  const float width0 = params.has("width0") ? params.get_float("width0") : width;
  const float width1 = params.has("width1") ? params.get_float("width1") : width;
  const CurveType type = read_type(params);
  std::vector<Vec3> normals = params.get_normals("N");
  if (!normals.empty() && type != CurveType::Ribbon) {
    params.warn_param("N", "normals are only used by \"ribbon\" curves; ignored (as pbrt-v4)");
    normals.clear();
  }
  if (type == CurveType::Ribbon) {
    if (normals.empty()) params.fail("N", "a \"ribbon\" curve needs normals \"N\" at its segment ends");
    if (normals.size() != size_t(*segments + 1))
      params.fail("N", fmt::format("{} normals given for {} segments: a ribbon needs {}", normals.size(), *segments,
                                   *segments + 1));
    for (size_t i = 0; i < normals.size(); ++i)
      if (!(glm::length(normals[i]) > 0.f) || !std::isfinite(glm::length(normals[i])))
        params.fail("N", fmt::format("normal {} is zero or not finite", i));
    for (size_t i = 0; i + 1 < normals.size(); ++i)
      if (glm::dot(glm::normalize(normals[i]), glm::normalize(normals[i + 1])) < -0.9999f)
        params.fail(
            "N", fmt::format("normals {} and {} are opposite: the ribbon's turn between them is undefined", i, i + 1));
  }
  (void)params.get_int("splitdepth");  // pbrt-v4's BVH granularity: Embree builds its own

  const std::vector<BezierSegment> beziers = cubic_bezier_segments(points, basis, degree);
  std::vector<CurveSegment> segs;
  const float n_seg = float(beziers.size());
  for (size_t s = 0; s < beziers.size(); ++s) {
    CurveSegment c;
    c.cp = beziers[s];
    // pbrt-v4: the width runs linearly over the whole curve, segment by segment.
    c.width0 = width0 + (width1 - width0) * float(s) / n_seg;
    c.width1 = width0 + (width1 - width0) * float(s + 1) / n_seg;
    if (type == CurveType::Ribbon) {
      c.n0 = glm::normalize(normals[s]);
      c.n1 = glm::normalize(normals[s + 1]);
    }
    segs.push_back(c);
  }
  const glm::mat3 m(ctx.world_from_object.matrix());
  const glm::mat3 mtm = glm::transpose(m) * m;
  const float s2 = mtm[0][0];
  if (std::abs(mtm[1][1] - s2) > 1e-4f * s2 || std::abs(mtm[2][2] - s2) > 1e-4f * s2 ||
      std::abs(mtm[0][1]) + std::abs(mtm[0][2]) + std::abs(mtm[1][2]) > 1e-4f * s2)
    warn(params.loc(),
         "curve: the transform scales non-uniformly; the width is scaled by its mean scale, where pbrt-v4 keeps it in "
         "object space");
  auto curve = std::make_unique<Curve>(segs, type, ctx.world_from_object, ctx.reverse_orientation);
  curve->set_alpha(read_alpha(ctx, params));
  std::vector<std::unique_ptr<Shape>> shapes;
  shapes.push_back(std::move(curve));
  return shapes;
}

}  // namespace eyetrace
