// Catmull-Rom splines over non-uniform nodes, as pbrt-v4 uses them for tabulated functions
// (the BSSRDF profile table): interpolation weights, evaluation, inversion of a monotone
// spline, its integral (with a running CDF), and sampling a spline in its second dimension with
// the first interpolated. Endpoint derivatives are one-sided finite differences.
#pragma once
#include <span>

namespace eyetrace {

// The four weights of nodes offset..offset+3 for x (a weight for a missing node is 0); false
// when x lies outside [nodes.front(), nodes.back()].
bool catmull_rom_weights(std::span<const float> nodes, float x, int* offset, float weights[4]);

// The spline through (nodes, f) at x; 0 outside the nodes.
float catmull_rom(std::span<const float> nodes, std::span<const float> f, float x);

// The x where a monotonically increasing spline (nodes, f) takes value u, clamped to the nodes.
float invert_catmull_rom(std::span<const float> nodes, std::span<const float> f, float u);

// The integral of the spline over the nodes; cdf[i] receives the integral up to nodes[i].
float integrate_catmull_rom(std::span<const float> nodes, std::span<const float> f, std::span<float> cdf);

// Samples x in [nodes2.front(), nodes2.back()] in proportion to the 2D spline table
// values[i * nodes2.size() + j] interpolated at alpha along nodes1, using its per-row CDFs
// (integrate_catmull_rom). Returns nodes2.front() when alpha lies outside nodes1. `fval`, `pdf`
// (optional): the interpolated function and its density at the result.
float sample_catmull_rom_2d(std::span<const float> nodes1, std::span<const float> nodes2, std::span<const float> values,
                            std::span<const float> cdf, float alpha, float u, float* fval = nullptr,
                            float* pdf = nullptr);

}  // namespace eyetrace
