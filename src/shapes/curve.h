// pbrt-v4's "curve": cubic Bezier segments (after curve_basis.h's conversion) swept to a band
// of linearly varying width, traced as pbrt-v4 intersects them: as a band facing each ray
// (Embree's flat curve), for all three types.
//  - "flat": that band.
//  - "cylinder": the same band with the normal bent as pbrt-v4 bends it: dp/dv turned about
//    the tangent by -theta, theta from -90 degrees at one edge (v = 0) to +90 at the other
//    (v = 1), linearly in v. That normal is a tube's back half (it leans along the ray), so
//    two-sided shading sees a mirrored tube: a side light brightens the far edge (checked
//    against pbrt-v4's own images). Reproduced on purpose, so pbrt-v4 scenes render as there.
//    Embree's round curve (a real tube) was not chosen: its hits lie up to a radius nearer,
//    its normal follows asin of the offset, and v would have to be made up, so pbrt-v4's
//    images (and the hair material's h) would not be matched.
//  - "ribbon": the band facing the ray narrowed to width |N . d| (N slerped from N[i] to
//    N[i+1] along the segment), as pbrt-v4 approximates an oriented ribbon; the normal is N.
//    Embree's normal-oriented curve (the true ribbon) was not chosen: it is wider than
//    pbrt-v4's when seen obliquely along the curve. The narrowing is an Embree filter.
// The interaction, as pbrt-v4 makes it: u runs 0..1 along each segment (pbrt-v4's u is per
// segment, not over the whole curve; a segment is one Bezier piece or one B-spline span),
// v runs 0..1 across the band, 0.5 on the centre line as the ray sees it (the hair material
// reads h = 2 v - 1), increasing along dp/dv; dp/du is the tangent, |dp/dv| the width seen.
// Embree's flat curves are polylines of at most 16 chords per primitive: segments so curved
// that 16 chords stray from the curve by more than width / 100 (see build_pieces) are
// split first. pbrt-v4's "splitdepth" only splits its BVH primitives: read and unused here.
// Area lights on curves are refused (pbrt-v4 aborts when sampling one).
// One difference that cannot be helped here: Embree ignores a curve hit closer to the ray's
// origin than the curve's width (its self-intersection avoidance, a build-time constant of the
// library), where pbrt-v4 takes any hit in front of the origin; hairs nearer each other than a
// width do not shadow each other. On 20,000 hairs of width 0.01 to 0.002 over a floor that made
// the image 0.4 % brighter than pbrt-v4's (up to 2 % where the hair is densest).
#pragma once
#include <memory>
#include <vector>

#include "core/transform.h"
#include "scene/registry.h"
#include "shapes/curve_basis.h"
#include "shapes/shape_alpha.h"

namespace eyetrace {

enum class CurveType { Flat, Cylinder, Ribbon };

// One input segment: object-space control points, width at u = 0 and 1, and (ribbons) the
// normals at its ends.
struct CurveSegment {
  BezierSegment cp;
  float width0 = 1.f, width1 = 1.f;
  Vec3 n0{0.f}, n1{0.f};
};

class Curve : public Shape {
 public:
  Curve(const std::vector<CurveSegment>& segments, CurveType type, const Transform& world_from_object,
        bool reverse_orientation);

  unsigned attach(RTCDevice device, RTCScene scene) const override;
  SurfaceInteraction interaction(const Ray& ray, float t, unsigned prim_id, Vec2 uv, Vec3 ng) const override;
  // The band's area, integral of width |dp/du| du (a flat band's as its ray sees it).
  float area() const override { return area_; }
  // Never called: the scene builder refuses area lights on curves (emitter_refusal).
  ShapeSample sample_area(Vec2 u) const override;
  Bounds3 bounds() const override { return bounds_; }
  // Embree primitives: the segments, some split for accuracy (see the top).
  size_t primitive_count() const override { return pieces_.size(); }
  const char* emitter_refusal() const override;

  void set_alpha(const ShapeAlpha& alpha) { alpha_ = alpha; }
  // Whether the ray (o, d) meets the surface where Embree's band hits piece `piece` at u,
  // distance t: inside a ribbon's narrower band, and not cut out by alpha.
  bool passes(unsigned piece, float u, const Vec3& o, const Vec3& d, float t) const;
  size_t segment_count() const { return segments_.size(); }

 private:
  struct Piece {  // an Embree primitive: segment `segment` from u0 to u1
    unsigned segment;
    float u0, u1;
  };
  struct Local {  // what a hit at segment u and point p means (see interaction())
    Vec2 uv;
    Vec3 n, dpdu, dpdv;
    float width;  // as the ray sees it (a ribbon's: width |N . d|)
    bool inside;  // within that width of the centre line
  };
  Local local_at(unsigned piece, float embree_u, const Vec3& p, const Vec3& d) const;
  Vec3 ribbon_normal(const CurveSegment& s, float u) const;
  void build_pieces();
  static void filter(const RTCFilterFunctionNArguments* args);

  std::vector<CurveSegment> segments_;  // world space, normals unit
  std::vector<Piece> pieces_;
  std::vector<Vec4> vertices_;  // 4 per piece: x y z radius
  std::vector<uint32_t> indices_;
  int tessellation_ = 4;  // Embree's pieces per flat segment
  CurveType type_;
  float handedness_;   // -1 when the transform mirrors (pbrt works in object space)
  float orientation_;  // -1 with ReverseOrientation
  float area_ = 0.f;
  Bounds3 bounds_;
  ShapeAlpha alpha_;
};

// "point3 P", "string basis", "integer degree", "string type", "normal N", "float width",
// "width0", "width1", "integer splitdepth", "alpha".
const PluginSpec& curve_shape_spec();
std::vector<std::unique_ptr<Shape>> create_curve_shapes(const ShapeContext& ctx);

}  // namespace eyetrace
