#include "media/nanovdb_medium.h"

#define NANOVDB_USE_ZIP  // zlib-compressed grids (eyetrace links zlib already)
#include <nanovdb/NanoVDB.h>
#include <nanovdb/util/IO.h>
#include <nanovdb/util/SampleFromVoxels.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "media/grid_medium.h"
#include "media/medium_params.h"
#include "scene/scene_files.h"

namespace eyetrace {

struct NanoVDBMedium::Grids {
  nanovdb::GridHandle<nanovdb::HostBuffer> density_handle, temperature_handle;
  const nanovdb::FloatGrid* density = nullptr;
  const nanovdb::FloatGrid* temperature = nullptr;
};

namespace {

using Trilinear = nanovdb::SampleFromVoxels<nanovdb::FloatGrid::TreeType, 1, false>;

float sample(const nanovdb::FloatGrid& grid, const Vec3& p) {
  const nanovdb::Vec3f index = grid.worldToIndexF(nanovdb::Vec3f(p.x, p.y, p.z));
  return Trilinear(grid.tree())(index);
}

Bounds3 world_bounds(const nanovdb::FloatGrid& grid) {
  const auto& b = grid.worldBBox();
  Bounds3 r;
  r.lo = Vec3(float(b.min()[0]), float(b.min()[1]), float(b.min()[2]));
  r.hi = Vec3(float(b.max()[0]), float(b.max()[1]), float(b.max()[2]));
  return r;
}

}  // namespace

NanoVDBMedium::NanoVDBMedium(const Transform& medium_from_render, Spectrum sigma_a, Spectrum sigma_s, float g,
                             std::unique_ptr<Grids> grids, Emission emission)
    : sigma_a_(std::move(sigma_a)), sigma_s_(std::move(sigma_s)), g_(g), grids_(std::move(grids)), emission_(emission) {
  box_.medium_from_render = medium_from_render;
  box_.bounds = world_bounds(*grids_->density);
  if (grids_->temperature) box_.bounds.extend(world_bounds(*grids_->temperature));
  majorant_grid_.bounds = box_.bounds;
  // Each majorant voxel: the largest density sample whose trilinear filter reaches into it
  // (its index-space range widened by one sample, clipped to the grid's active bounds).
  const nanovdb::FloatGrid& d = *grids_->density;
  const auto index_box = d.indexBBox();
  auto accessor = d.getAccessor();
  const int n = majorant_grid_.res;
  const Vec3 extent = box_.bounds.hi - box_.bounds.lo;
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const Bounds3 u = majorant_grid_.voxel_bounds(x, y, z);
        const Vec3 w0 = box_.bounds.lo + u.lo * extent, w1 = box_.bounds.lo + u.hi * extent;
        const nanovdb::Vec3d i0 = d.worldToIndexF(nanovdb::Vec3d(w0.x, w0.y, w0.z));
        const nanovdb::Vec3d i1 = d.worldToIndexF(nanovdb::Vec3d(w1.x, w1.y, w1.z));
        int lo[3], hi[3];
        for (int a = 0; a < 3; ++a) {
          // A negative scale in the index map would swap the ends: order them.
          const double a0 = std::min(i0[a], i1[a]), a1 = std::max(i0[a], i1[a]);
          lo[a] = std::max(int(std::floor(a0)) - 1, index_box.min()[a]);
          hi[a] = std::min(int(std::floor(a1)) + 1, index_box.max()[a]);
        }
        float m = 0.f;
        for (int k = lo[2]; k <= hi[2]; ++k)
          for (int j = lo[1]; j <= hi[1]; ++j)
            for (int i = lo[0]; i <= hi[0]; ++i) m = std::max(m, accessor.getValue(nanovdb::Coord(i, j, k)));
        majorant_grid_.set(x, y, z, m);
      }
}

NanoVDBMedium::~NanoVDBMedium() = default;

bool NanoVDBMedium::emissive() const { return grids_->temperature && emission_.Le_scale > 0.f; }

float NanoVDBMedium::density_in_medium_space(const Vec3& p) const { return sample(*grids_->density, p); }

MediumProperties NanoVDBMedium::properties(const Vec3& p_render, const SampledWavelengths& lambda) const {
  const Vec3 p = box_.to_medium(p_render);
  const float d = sample(*grids_->density, p);
  MediumProperties mp{sigma_a_.sample(lambda) * d, sigma_s_.sample(lambda) * d, SampledSpectrum(0.f), g_};
  if (emissive()) {
    const float kelvin = (sample(*grids_->temperature, p) - emission_.temperature_offset) * emission_.temperature_scale;
    if (kelvin > 100.f) {
      // pbrt-v4's film units (media/grid_medium.cpp says why).
      const float scale = emission_.Le_scale * cie_y_integral();
      for (int i = 0; i < kSpectrumSamples; ++i) mp.Le[i] = scale * normalized_blackbody(lambda[i], kelvin);
    }
  }
  return mp;
}

MajorantIterator NanoVDBMedium::majorants(const Ray& ray, float t_max, const SampledWavelengths& lambda) const {
  const auto c = box_.clip(ray, t_max);
  if (!c) return MajorantIterator();
  return MajorantIterator(c->o, c->d, c->t0, c->t1, &majorant_grid_, sigma_a_.sample(lambda) + sigma_s_.sample(lambda));
}

const PluginSpec& nanovdb_medium_spec() {
  static const PluginSpec spec{
      "MakeNamedMedium",
      "density (and temperature: blackbody emission) from a NanoVDB file, trilinear",
      "Reads uncompressed and zlib-compressed grids (pbrt-v4: uncompressed); Blosc-compressed ones are an error. "
      "Accepts `LeScale`, the spelling the collection's explosion scene uses, which today's pbrt-v4 refuses.",
      {param::string("filename").describe("the .nvdb file (required)"),
       param::string("gridname", "density").describe("the density grid's name"),
       param::string("temperaturename", "temperature").describe("the temperature grid's name (optional in the file)"),
       param::spectrum("sigma_a", 1).describe("absorption coefficient at density 1, per unit length"),
       param::spectrum("sigma_s", 1).describe("scattering coefficient at density 1, per unit length"),
       param::real("scale", 1).at_least(0).describe("multiplies `sigma_a` and `sigma_s`"),
       param::real("g", 0).describe("Henyey-Greenstein asymmetry, in (-1, 1)"),
       param::real("Lescale", 1).at_least(0).describe("multiplies the temperature's blackbody emission"),
       param::real("LeScale").at_least(0).describe("an older spelling of `Lescale` (not with it)"),
       param::real("temperatureoffset").describe("subtracted from the temperature (default `temperaturecutoff`)"),
       param::real("temperaturecutoff", 0).describe("pbrt-v4's older name for `temperatureoffset`"),
       param::real("temperaturescale", 1).describe("multiplies the offset temperature, giving kelvin")}};
  return spec;
}

namespace {

// The named float grid of the file, or an empty handle when the file has no grid of that name.
// Unreadable files and grids that are not float fog volumes are errors naming the parameter.
nanovdb::GridHandle<nanovdb::HostBuffer> read_grid(const PluginParams& p, const std::string& path,
                                                   const std::string& grid_name, const std::string& param) {
  nanovdb::GridHandle<nanovdb::HostBuffer> handle;
  try {
    handle = nanovdb::io::readGrid<nanovdb::HostBuffer>(path, grid_name, 0);
  } catch (const std::exception& e) {
    p.fail("filename", fmt::format("\"{}\": cannot read NanoVDB grid \"{}\": {}", path, grid_name, e.what()));
  }
  if (!handle) return handle;
  const nanovdb::GridMetaData* meta = handle.gridMetaData();
  if (!meta || !handle.grid<float>())
    p.fail(param, fmt::format("\"{}\": grid \"{}\" is not a float grid", path, grid_name));
  if (!meta->isFogVolume() && !meta->isUnknown())
    p.fail(param, fmt::format("\"{}\": grid \"{}\" is not a fog volume (pbrt-v4 reads only those)", path, grid_name));
  return handle;
}

}  // namespace

std::unique_ptr<Medium> create_nanovdb_medium(const MediumContext& ctx) {
  const PluginParams p(ctx.params, nanovdb_medium_spec(), "nanovdb");
  if (!p.has("filename")) p.fail("filename", "a nanovdb medium needs a \"filename\"");
  const std::string path = resolve_scene_file(ctx.search_dir, p.get_string("filename"));
  if (!std::filesystem::is_regular_file(path))
    p.fail_missing_file("filename", fmt::format("NanoVDB file \"{}\" not found", path));
  auto grids = std::make_unique<NanoVDBMedium::Grids>();
  grids->density_handle = read_grid(p, path, p.get_string("gridname"), "gridname");
  if (!grids->density_handle)
    p.fail("gridname", fmt::format("\"{}\" has no grid named \"{}\"", path, p.get_string("gridname")));
  grids->density = grids->density_handle.grid<float>();
  grids->temperature_handle = read_grid(p, path, p.get_string("temperaturename"), "temperaturename");
  if (grids->temperature_handle) grids->temperature = grids->temperature_handle.grid<float>();
  // A negative density would make the medium add light: refused, as in the other grids.
  float lo = 0.f, hi = 0.f;
  grids->density->tree().extrema(lo, hi);
  if (lo < 0.f || !std::isfinite(lo) || !std::isfinite(hi))
    p.fail("filename", fmt::format("\"{}\": density grid values range over [{}, {}]: must be finite and not negative",
                                   path, lo, hi));
  const Bounds3 b = world_bounds(*grids->density);
  if (b.empty()) p.fail("filename", fmt::format("\"{}\": the density grid is empty", path));
  NanoVDBMedium::Emission e;
  if (p.has("LeScale") && p.has("Lescale")) p.fail("LeScale", "and \"Lescale\" are both given: they are one parameter");
  e.Le_scale = p.has("LeScale") ? p.get_float("LeScale") : p.get_float("Lescale");
  e.temperature_offset =
      p.has("temperatureoffset") ? p.get_float("temperatureoffset") : p.get_float("temperaturecutoff");
  e.temperature_scale = p.get_float("temperaturescale");
  const float scale = p.get_float("scale");
  return std::make_unique<NanoVDBMedium>(ctx.world_from_medium.inverse(), coefficient_param(p, "sigma_a").scaled(scale),
                                         coefficient_param(p, "sigma_s").scaled(scale), asymmetry_param(p),
                                         std::move(grids), e);
}

}  // namespace eyetrace
