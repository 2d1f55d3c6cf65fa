// pbrt-v4's "nanovdb" medium (its NanoVDBMedium): the density (grid "density", or
// "gridname") and optionally the temperature (grid "temperature", or "temperaturename") of a
// NanoVDB file (.nvdb, read with Debian's libnanovdb-dev; uncompressed or zlib-compressed
// grids), looked up trilinearly in the grids' index space (NanoVDB's SampleFromVoxels, order
// 1, as pbrt-v4) at the point in the medium's space (the file's world space). sigma_a and
// sigma_s (times "scale") are multiplied by the density; the temperature emits a blackbody
// at (T - temperatureoffset) * temperaturescale kelvin (normalised to peak 1; none at or below
// 100 K) times "Lescale", in pbrt-v4's film units. Majorants: the density's maxima over a 64^3
// grid spanning the grids' world bounds (each voxel's index range widened by one sample for the
// filter, as pbrt-v4), walked by 3-D DDA.
#pragma once
#include <memory>
#include <string>

#include "core/medium.h"
#include "core/spectrum.h"
#include "media/medium_box.h"
#include "scene/registry.h"

namespace eyetrace {

class NanoVDBMedium : public Medium {
 public:
  struct Grids;  // the NanoVDB handles (nanovdb_medium.cpp)
  struct Emission {
    float Le_scale = 1.f, temperature_offset = 0.f, temperature_scale = 1.f;
  };
  NanoVDBMedium(const Transform& medium_from_render, Spectrum sigma_a, Spectrum sigma_s, float g,
                std::unique_ptr<Grids> grids, Emission emission);
  ~NanoVDBMedium() override;
  using Medium::properties;
  MediumProperties properties(const Vec3& p, const SampledWavelengths& lambda) const override;
  MajorantIterator majorants(const Ray& ray, float t_max, const SampledWavelengths& lambda) const override;
  bool emissive() const override;
  // The density at a point of the medium's space (tests).
  float density_in_medium_space(const Vec3& p) const;
  const MajorantGrid& majorant_grid() const { return majorant_grid_; }
  const Bounds3& bounds() const { return box_.bounds; }

 private:
  MediumBox box_;
  Spectrum sigma_a_, sigma_s_;
  float g_;
  std::unique_ptr<Grids> grids_;
  Emission emission_;
  MajorantGrid majorant_grid_{64};
};

const PluginSpec& nanovdb_medium_spec();
std::unique_ptr<Medium> create_nanovdb_medium(const MediumContext& ctx);

}  // namespace eyetrace
