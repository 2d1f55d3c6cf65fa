#include "shapes/loop_subdiv_mesh.h"

#include "shapes/loop_subdivision.h"
#include "shapes/shape_alpha.h"
#include "shapes/triangle_mesh.h"

namespace eyetrace {

const PluginSpec& loopsubdiv_shape_spec() {
  static const PluginSpec spec{
      "Shape",
      "a Loop subdivision surface: a triangle control mesh refined and pushed to its limit surface",
      "Boundary vertices go to the limit of the boundary's cubic B-spline (mask 1/6, 2/3, 1/6), where pbrt-v4's "
      "mask 1/5, 3/5, 1/5 is not the limit; the control mesh must be a consistently oriented manifold (pbrt-v4 "
      "assumes it unchecked; eyetrace names the triangle, edge or vertex that breaks it).",
      {param::point3s("P").shown_default("required").describe("control vertex positions"),
       param::integers("indices").shown_default("required").describe("3 per control triangle"),
       param::integer("levels", 3)
           .range(0, 12)
           .describe("subdivision steps (4^levels triangles per control "
                     "triangle, at most 2^26 in all)"),
       param::string("scheme", "loop")
           .in({"loop"})
           .describe("pbrt-v4 reads it and uses Loop's scheme whatever it says"),
       alpha_param()}};
  return spec;
}

std::vector<std::unique_ptr<Shape>> create_loopsubdiv_shapes(const ShapeContext& ctx) {
  const PluginParams params(ctx.params, loopsubdiv_shape_spec(), "loopsubdiv");
  const std::vector<Vec3> positions = params.get_point3s("P");
  const std::vector<int> indices = params.get_ints("indices");
  if (positions.empty()) params.fail("P", "the control mesh has no vertex positions");
  if (indices.empty()) params.fail("indices", "the control mesh's vertex indices are required");
  MeshData mesh;
  try {
    mesh = loop_subdivide(positions, indices, params.get_int("levels"));
  } catch (const LoopSubdivisionError& e) {
    params.fail(
        params.has("levels") && std::string(e.what()).find("levels") != std::string::npos ? "levels" : "indices",
        e.what());
  }
  std::vector<std::unique_ptr<Shape>> shapes;
  shapes.push_back(make_mesh_shape(std::move(mesh), ctx, params, MeshSource{ctx.params}));
  return shapes;
}

}  // namespace eyetrace
