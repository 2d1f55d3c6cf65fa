// pbrt lens-file reader (format and film placement: see lens_file.h).
#include "optics/lens_file.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "optics/optics_error.h"
#include "optics/paraxial.h"

namespace eyetrace::optics {

namespace {

struct Row {
  int line;
  double values[5];
  int count;
};

std::string medium_name(double index) { return index == 1.0 ? std::string("air") : fmt::format("n={:.6g}", index); }

std::vector<Row> read_rows(const std::string& text, const std::string& file) {
  std::vector<Row> rows;
  std::istringstream in(text);
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (const size_t hash = line.find('#'); hash != std::string::npos) line.resize(hash);
    std::istringstream fields(line);
    std::string token;
    Row row{number, {0, 0, 0, 0, 0}, 0};
    int found = 0;
    while (fields >> token) {
      double v = 0.0;
      const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), v);
      if (ec != std::errc() || end != token.data() + token.size() || !std::isfinite(v))
        throw OpticsError(fmt::format("{}:{}: '{}' is not a number", file, number, token));
      if (found < 5) row.values[found] = v;
      ++found;
    }
    if (found == 0) continue;
    if (found != 4 && found != 5)
      throw OpticsError(
          fmt::format("{}:{}: expected 4 or 5 numbers (radius thickness index "
                      "aperture [conic]), found {}",
                      file, number, found));
    row.count = found;
    rows.push_back(row);
  }
  return rows;
}

}  // namespace

Prescription parse_lens_file(const std::string& text, const std::string& file, const LensFileOptions& options) {
  const std::vector<Row> rows = read_rows(text, file);
  if (rows.empty()) throw OpticsError(fmt::format("{}: no lens interfaces", file));

  Prescription p;
  p.name = file;
  p.source = fmt::format("pbrt-v4 lens file {}", file);
  p.notes.push_back("pbrt lens files give one index per glass: no dispersion; nominal 589.3 nm");
  double index_before = 1.0;
  int stops = 0;
  for (size_t i = 0; i < rows.size(); ++i) {
    const Row& r = rows[i];
    const double radius = r.values[0], thickness = r.values[1], aperture = r.values[3];
    const double eta = r.values[2] == 0.0 ? 1.0 : r.values[2];
    const std::string where = fmt::format("{}:{}", file, r.line);
    if (thickness < 0.0) throw OpticsError(fmt::format("{}: thickness {} mm is negative", where, thickness));
    if (aperture <= 0.0)
      throw OpticsError(fmt::format("{}: aperture diameter {} mm must be positive", where, aperture));
    if (eta < 1.0) throw OpticsError(fmt::format("{}: index {} is below 1", where, eta));
    Surface s;
    s.thickness_mm = thickness;
    s.semi_diameter_mm = 0.5 * aperture;
    if (radius == 0.0) {
      if (r.values[2] != 0.0 && eta != index_before)
        throw OpticsError(
            fmt::format("{}: the aperture stop (radius 0) must not change the "
                        "index ({} before, {} after)",
                        where, index_before, eta));
      if (r.count == 5 && r.values[4] != 0.0)
        throw OpticsError(fmt::format("{}: the aperture stop cannot have a conic", where));
      s.name = "aperture stop";
      s.role = SurfaceRole::Stop;
      s.index_after = index_before;
      if (options.aperture_diameter_mm) {
        const double d = *options.aperture_diameter_mm;
        if (!(d > 0.0 && d <= aperture))
          throw OpticsError(
              fmt::format("{}: aperture diameter {} mm must be in (0, {}] mm "
                          "(the stop's diameter in the file)",
                          where, d, aperture));
        s.semi_diameter_mm = 0.5 * d;
      }
      ++stops;
    } else {
      s.name = fmt::format("interface {} (line {})", i, r.line);
      s.profile = SurfaceProfile::from_radius(radius, r.count == 5 ? r.values[4] : 0.0);
      s.index_after = eta;
    }
    s.medium = medium_name(s.index_after);
    if (!p.find_medium(s.medium)) p.media.push_back({s.medium, s.index_after, 589.3, {}});
    index_before = s.index_after;
    p.surfaces.push_back(s);
  }
  if (stops != 1)
    throw OpticsError(fmt::format("{}: expected one aperture stop (a row with radius 0), found {}", file, stops));
  Surface film;
  film.name = "film";
  film.role = SurfaceRole::Image;
  film.medium = p.surfaces.back().medium;
  film.index_after = index_before;
  p.surfaces.push_back(film);

  try {
    if (options.focus_distance_m) {
      const double d = *options.focus_distance_m;
      if (!(d > 0.0)) throw OpticsError(fmt::format("focus distance {} m must be positive", d));
      set_refraction(p, std::isinf(d) ? 0.0 : -1.0 / d);
      p.notes.push_back(fmt::format("film placed at the paraxial focus for {} m", d));
    } else if (p.surfaces[p.surfaces.size() - 2].thickness_mm == 0.0) {
      set_refraction(p, 0.0);
      p.notes.push_back("last thickness 0: film placed at the paraxial focus for infinity");
    }
    validate(p);
  } catch (const OpticsError& e) {
    throw OpticsError(fmt::format("{}: {}", file, e.what()));
  }
  return p;
}

Prescription read_lens_file(const std::string& path, const LensFileOptions& options) {
  std::ifstream in(path, std::ios::binary);
  const std::string name = path.substr(path.find_last_of("/\\") + 1);
  if (!in) throw OpticsError(fmt::format("{}: cannot open '{}'", name, path));
  std::ostringstream text;
  text << in.rdbuf();
  return parse_lens_file(text.str(), name, options);
}

}  // namespace eyetrace::optics
