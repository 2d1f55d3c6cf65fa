#include "integrators/subsurface_exit.h"

#include <algorithm>

#include "render/segment_hits.h"

namespace eyetrace {

std::optional<SubsurfaceExit> sample_subsurface_exit(const Scene& scene, const BSSRDF& bssrdf,
                                                     const SurfaceInteraction& entry, const SampledWavelengths& lambda,
                                                     Sampler& sampler, ScratchBuffer& arena, RayTally& tally) {
  const float u_axis = sampler.get_1d();
  const Vec2 u_radius = sampler.get_2d();
  // Uniform reservoir sampling with one uniform number: the k-th candidate replaces the kept
  // one with probability 1/k, and u is rescaled to stay uniform for the next decision (a few
  // hits per probe, so the float precision lost per step does not matter).
  float u_choice = sampler.get_1d();
  const std::optional<BSSRDFProbeSegment> seg = bssrdf.sample_sp(u_axis, u_radius);
  if (!seg) return std::nullopt;
  SurfaceInteraction chosen;
  int candidates = 0;
  tally.rays += for_each_hit_on_segment(scene, seg->p0, seg->p1, entry.time, [&](const SurfaceInteraction& si) {
    if (si.material != entry.material) return;
    ++candidates;
    const float p = 1.f / float(candidates);
    if (u_choice < p) {
      chosen = si;
      u_choice = std::min(u_choice / p, 0x1.fffffep-1f);
    } else {
      u_choice = std::min((u_choice - p) / (1.f - p), 0x1.fffffep-1f);
    }
  });
  if (candidates == 0) return std::nullopt;
  const BSSRDFSample bs = bssrdf.probe_intersection_to_sample(chosen, arena);
  if (!(bs.pdf[0] > 0.f) || is_black(bs.sp) || !is_finite(bs.sp) || !is_finite(bs.pdf)) return std::nullopt;
  SubsurfaceExit exit;
  exit.si = chosen;
  exit.si.wo = chosen.ns;
  exit.sw = bs.sw;
  exit.sp = bs.sp;
  exit.pdf = bs.pdf / float(candidates);
  return exit;
}

}  // namespace eyetrace
