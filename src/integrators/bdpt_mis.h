// The multiple-importance-sampling weight of one bidirectional path tracing strategy (pbrt-v4's
// MISWeight), from the vertex densities alone so that it can be checked on its own. pbrt-v4
// uses the balance heuristic here (its path integrator uses the power heuristic). A path of n
// vertices x_0 (camera) ... x_{n-1} (light) is made by strategy (s, t), s + t = n, from t
// camera vertices and s light vertices. Its weight is
//   w_{s,t} = p_{s,t} / sum over usable strategies (s', t') of p_{s',t'},
// written as 1 / (1 + sum of p_{s',t'} / p_{s,t}), where each ratio is a running product
// of pdf_rev / pdf_fwd along the path. Usable strategies: t' >= min_t (eyetrace's renderer does
// not use t = 0, and t = 1 only where the camera can be connected to), and neither vertex of
// the connection is specular (delta); s' = 0 also needs a light that can be hit (not delta).
#pragma once

namespace eyetrace {

struct BdptDensities {
  // Density of the vertex per unit area (solid angle where it is at infinity) when the subpath
  // it belongs to generates it (pdf_fwd), and when the other subpath would (pdf_rev). Zero for
  // a specular vertex's own sampled direction: it counts as 1 (it cancels between strategies).
  float pdf_fwd = 0.f;
  float pdf_rev = 0.f;
  bool delta = false;  // a specular scattering vertex
};

// camera[0..t-1] and light[0..s-1] as the connection of strategy (s, t) leaves them (its two
// connection vertices and their neighbours' pdf_rev already updated for this connection);
// delta_light: light[0]'s light is a point, spot or distant light (no path can hit it).
// min_t: the fewest camera vertices a strategy the renderer uses has (2, or 1 with light tracing).
float bdpt_mis_weight(const BdptDensities* camera, int t, const BdptDensities* light, int s, bool delta_light,
                      int min_t);

}  // namespace eyetrace
