// The NanoVDB volume of tests/data/pbrt-v4/nanovdb.pbrt, written by code rather than stored
// (an .nvdb file of two 16^3 grids is 645 kB, mostly NanoVDB's fixed upper tree nodes): a lumpy
// ball of density (up to about 4.5) and a temperature grid (5 to 25), 16^3 voxels of 1/8,
// uncompressed, float fog volumes "density" and "temperature". pbrt-v4's reference images were
// rendered from the file this writes (PROVENANCE: built with NanoVDB 32.4, Debian's
// libnanovdb-dev; pbrt-v4 reads it with its own NanoVDB 32.3, the same file format).
#pragma once
#include <nanovdb/util/GridBuilder.h>
#include <nanovdb/util/IO.h>

#include <cmath>
#include <string>
#include <vector>

namespace eyetrace::test {

inline void write_nanovdb_smoke(const std::string& path) {
  const int n = 16;
  nanovdb::GridBuilder<float> d(0.f, nanovdb::GridClass::FogVolume), t(0.f, nanovdb::GridClass::FogVolume);
  auto da = d.getAccessor();
  auto ta = t.getAccessor();
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const double x = (i + 0.5) / n - 0.5, y = (j + 0.5) / n - 0.5, z = (k + 0.5) / n - 0.5;
        const double r = std::sqrt(x * x + y * y + z * z);
        const double lump = 1.0 + 0.5 * std::sin(9 * x) * std::cos(7 * y + 2 * z);
        const double v = r < 0.45 ? lump * (0.45 - r) / 0.45 * 3.0 : 0.0;
        if (v > 0) {
          da.setValue(nanovdb::Coord(i, j, k), float(v));
          ta.setValue(nanovdb::Coord(i, j, k), float(5 + 20 * (0.45 - r) / 0.45));
        }
      }
  std::vector<nanovdb::GridHandle<nanovdb::HostBuffer>> grids;
  grids.push_back(d.getHandle<>(1.0 / 8, nanovdb::Vec3d(0.0), "density"));
  grids.push_back(t.getHandle<>(1.0 / 8, nanovdb::Vec3d(0.0), "temperature"));
  nanovdb::io::writeGrids(path, grids);
}

}  // namespace eyetrace::test
