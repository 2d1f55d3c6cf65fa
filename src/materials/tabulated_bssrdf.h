// pbrt-v4's TabulatedBSSRDF: the radial profile Sr of a homogeneous medium read from a
// BSSRDFTable (optical radius r sigma_t, albedo sigma_s / sigma_t) by 2D Catmull-Rom
// interpolation, per wavelength; its importance sampling at the hero wavelength (radius from
// the table's CDF, then a probe segment along one of three axes around the entry's shading
// normal: 1/4, 1/4, 1/2), and the exit point's density over the surface from all three axes.
#pragma once
#include <optional>

#include "core/bssrdf.h"
#include "materials/bssrdf_table.h"

namespace eyetrace {

class TabulatedBSSRDF final : public BSSRDF {
 public:
  // po, ns: the entry point and its shading normal; eta: the boundary's relative index.
  TabulatedBSSRDF(const Vec3& po, const Vec3& ns, float eta, const SampledSpectrum& sigma_a,
                  const SampledSpectrum& sigma_s, const BSSRDFTable* table);

  // Sr(r) per wavelength, in inverse square scene units.
  SampledSpectrum sr(float r) const;
  // A radius sampled in proportion to r Sr(r) at the hero wavelength (empty if sigma_t is 0).
  std::optional<float> sample_sr(float u) const;
  // Density of sample_sr's radius per unit area (r Sr(r) / rho_eff normalised), per wavelength.
  SampledSpectrum pdf_sr(float r) const;
  // Density of the exit point pi (normal ni) per unit area, over the three projection axes.
  SampledSpectrum pdf_sp(const Vec3& pi, const Vec3& ni) const;

  std::optional<BSSRDFProbeSegment> sample_sp(float u1, Vec2 u2) const override;
  BSSRDFSample probe_intersection_to_sample(const SurfaceInteraction& exit, ScratchBuffer& arena) const override;

 private:
  // Interpolated table value at (rho[i], r sigma_t[i]) divided by 2 pi r_optical, and the
  // interpolated rho_eff; false outside the table.
  bool profile_at(int i, float r, float* sr, float* rho_eff) const;

  Vec3 po_;
  Frame frame_;  // around the entry's shading normal
  float eta_;
  SampledSpectrum sigma_t_, rho_;
  const BSSRDFTable* table_;
};

}  // namespace eyetrace
