// Triangle meshes: pbrt-v4's "trianglemesh" shape and the common target of "plymesh",
// "bilinearmesh" and procedural meshes. Embree traces the triangles natively (no callback
// per traversal step); this class only turns a hit into an interaction and samples by area.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/shape.h"
#include "core/texture.h"
#include "core/transform.h"
#include "scene/registry.h"
#include "shapes/shape_alpha.h"

namespace eyetrace {

// A mesh as read from a scene or file, in object space, before validation.
struct MeshData {
  std::vector<Vec3> positions;
  std::vector<int> indices;   // 3 per triangle
  std::vector<Vec3> normals;  // per vertex, or empty
  std::vector<Vec2> uvs;      // per vertex, or empty
};

// Where a mesh came from, so that validation errors name the parameter the user wrote:
// "P", "indices", ... for inline meshes, "filename" (with `context` naming the file) for
// meshes read from files.
struct MeshSource {
  explicit MeshSource(const ParameterList& p) : params(p) {}
  const ParameterList& params;
  std::string p = "P", indices = "indices", n = "N", uv = "uv";
  std::string context;  // prefix for messages, e.g. "file \"bunny.ply\": "
};

class TriangleMesh : public Shape {
 public:
  // Validates `mesh` (indices in range and a multiple of 3, per-vertex arrays as long as
  // "P", finite world positions), moves it to world space and drops zero-area triangles
  // with one counted warning. An empty result is an error.
  TriangleMesh(MeshData mesh, const Transform& world_from_object, bool reverse_orientation, const MeshSource& source);

  unsigned attach(RTCDevice device, RTCScene scene) const override;
  SurfaceInteraction interaction(const Ray& ray, float t, unsigned prim_id, Vec2 uv, Vec3 ng) const override;
  float area() const override { return area_; }
  ShapeSample sample_area(Vec2 u) const override;
  Bounds3 bounds() const override { return bounds_; }
  size_t primitive_count() const override { return indices_.size() / 3; }
  bool alpha_masked(const TextureEvalContext& ctx) const override { return alpha_.masks(ctx); }
  bool invisible() const override { return alpha_.invisible(); }

  size_t vertex_count() const { return vertex_count_; }
  int dropped_triangles() const { return dropped_; }

  // Alpha cutouts (shape_alpha.h): an Embree filter function applies them to intersections and
  // shadow rays alike; for an opaque mesh (the default) none is installed.
  void set_alpha(const ShapeAlpha& alpha) { alpha_ = alpha; }
  // Whether a ray (o, d) hitting triangle `tri` at Embree's barycentrics (b1, b2), distance t,
  // meets the surface there; public for tests.
  bool alpha_passes(unsigned tri, float b1, float b2, const Vec3& o, const Vec3& d, float t) const;

 private:
  struct Corner {
    Vec3 p[3];
    Vec2 uv[3];
  };
  Corner corners(unsigned tri) const;
  // Error box of any hit or sample point b0 p0 + b1 p1 + b2 p2 of a triangle: the rounding of
  // that sum, bounded over all barycentrics, plus embree_plane_error (see the .cpp).
  static Vec3 triangle_error(const Corner& c);
  // Distance from the triangle's plane within which Embree's float test may misjudge the side.
  static float embree_plane_error(const Corner& c);
  // Geometric normal oriented as pbrt orients it (see the .cpp), and the shading normal.
  void normals_at(unsigned tri, float b0, float b1, float b2, Vec3* n, Vec3* ns) const;
  void validate(MeshData& mesh, const MeshSource& source) const;
  static void alpha_filter(const RTCFilterFunctionNArguments* args);
  void build(MeshData& mesh, const Transform& world_from_object, const MeshSource& source);

  // World-space positions with one padding element at the end: Embree reads vertex buffers
  // 16 bytes at a time, so the last 12-byte vertex must be followed by 4 readable bytes.
  std::vector<Vec3> positions_;
  size_t vertex_count_ = 0;
  std::vector<uint32_t> indices_;
  std::vector<Vec3> normals_;  // world space, reverse orientation applied; may be empty
  std::vector<Vec2> uvs_;
  std::vector<double> cdf_;        // cumulative triangle area / total, for area sampling
  std::vector<Vec3> point_error_;  // triangle_error of each kept triangle
  std::vector<Vec3> face_normal_;  // robust_normalize(cross(p0 - p2, p1 - p2)), unflipped
  float area_ = 0.f;
  ShapeAlpha alpha_;
  Bounds3 bounds_;
  bool flip_normal_ = false;  // reverse_orientation XOR transform swaps handedness
  int dropped_ = 0;
};

// A mesh shape as every plugin that makes triangles builds it: in the world through ctx's
// transform and orientation, cut out by the shape's "alpha"; `source` names the parameters
// validation errors point at.
std::unique_ptr<TriangleMesh> make_mesh_shape(MeshData mesh, const ShapeContext& ctx, const PluginParams& params,
                                              const MeshSource& source);

// pbrt-v4 "trianglemesh": "point3 P", "integer indices" (optional for exactly 3 vertices),
// "normal N", "point2 uv", "vector3 S" (ignored with a warning), "integer faceIndices".
std::vector<std::unique_ptr<Shape>> create_trianglemesh_shapes(const ShapeContext& ctx);

const PluginSpec& trianglemesh_shape_spec();

}  // namespace eyetrace
