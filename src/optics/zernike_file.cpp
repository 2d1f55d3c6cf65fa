// Zernike wavefront file reader (format: see zernike_file.h).
#include "optics/zernike_file.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "optics/medium.h"
#include "optics/optics_error.h"
#include "optics/zernike.h"

namespace eyetrace::optics {

namespace {

enum class Ordering { Unset, Osa, Nm };

struct Reader {
  const std::string& origin;
  int line = 0;

  [[noreturn]] void fail(const std::string& what) const {
    throw OpticsError(fmt::format("{}:{}: {}", origin, line, what));
  }

  // The whole token as a finite number (from_chars: no locale, no trailing garbage).
  double number(const std::string& token, const char* what) const {
    double v = 0.0;
    const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), v);
    if (ec != std::errc() || end != token.data() + token.size() || !std::isfinite(v))
      fail(fmt::format("{} '{}' is not a finite number", what, token));
    return v;
  }

  int integer(const std::string& token, const char* what) const {
    int v = 0;
    const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), v);
    if (ec != std::errc() || end != token.data() + token.size())
      fail(fmt::format("{} '{}' is not an integer", what, token));
    return v;
  }
};

std::vector<std::string> tokens_of(std::string line) {
  if (const size_t hash = line.find('#'); hash != std::string::npos) line.resize(hash);
  std::istringstream in(line);
  std::vector<std::string> out;
  for (std::string t; in >> t;) out.push_back(t);
  return out;
}

// (n, m) of one coefficient line, checked against the supported orders.
ZernikeIndex index_of(const Reader& r, const std::vector<std::string>& t, Ordering ordering) {
  if (ordering == Ordering::Osa) {
    if (t.size() != 2) r.fail(fmt::format("ordering osa expects 'j coefficient_um', found {} fields", t.size()));
    const int j = r.integer(t[0], "OSA index");
    const int last = zernike_term_count(kMaxZernikeFileOrder) - 1;
    if (j < 0 || j > last)
      r.fail(fmt::format("OSA index {} is outside 0..{} (radial orders 0..{} are supported)", j, last,
                         kMaxZernikeFileOrder));
    return zernike_index(j);
  }
  if (t.size() != 3) r.fail(fmt::format("ordering nm expects 'n m coefficient_um', found {} fields", t.size()));
  const ZernikeIndex z{r.integer(t[0], "radial order n"), r.integer(t[1], "frequency m")};
  if (z.n < 0 || std::abs(z.m) > z.n || (z.n - std::abs(z.m)) % 2 != 0)
    r.fail(fmt::format("(n, m) = ({}, {}) names no Zernike polynomial (|m| <= n, n - |m| even)", z.n, z.m));
  if (z.n > kMaxZernikeFileOrder)
    r.fail(fmt::format("radial order {} is beyond the supported {}", z.n, kMaxZernikeFileOrder));
  return z;
}

}  // namespace

ZernikeFile parse_zernike_text(const std::string& text, const std::string& origin) {
  ZernikeFile out;
  out.origin = origin;
  Reader r{origin};
  Ordering ordering = Ordering::Unset;
  int pupil_line = 0, wavelength_line = 0, ordering_line = 0;
  std::vector<int> seen(static_cast<size_t>(zernike_term_count(kMaxZernikeFileOrder)), 0);  // line of each j
  out.coefficients_um.assign(seen.size(), 0.0);
  std::istringstream in(text);
  std::string line;
  for (r.line = 1; std::getline(in, line); ++r.line) {
    const std::vector<std::string> t = tokens_of(line);
    if (t.empty()) continue;
    const std::string& key = t[0];
    auto once = [&](int& at) {
      if (at) r.fail(fmt::format("'{}' given again (first on line {})", key, at));
      if (t.size() != 2) r.fail(fmt::format("'{}' takes one value, found {}", key, t.size() - 1));
      at = r.line;
    };
    if (key == "pupil_diameter_mm") {
      once(pupil_line);
      out.pupil_diameter_mm = r.number(t[1], "pupil_diameter_mm");
      if (!(out.pupil_diameter_mm > 0.0 && out.pupil_diameter_mm <= kMaxZernikePupil_mm))
        r.fail(fmt::format("pupil_diameter_mm {} is outside (0, {}] mm", t[1], kMaxZernikePupil_mm));
    } else if (key == "wavelength_nm") {
      once(wavelength_line);
      out.wavelength_nm = r.number(t[1], "wavelength_nm");
      if (!(out.wavelength_nm >= kMinWavelength_nm && out.wavelength_nm <= kMaxWavelength_nm))
        r.fail(fmt::format("wavelength_nm {} is outside [{}, {}] nm", t[1], kMinWavelength_nm, kMaxWavelength_nm));
    } else if (key == "ordering") {
      once(ordering_line);
      if (t[1] == "osa" || t[1] == "ansi") {
        ordering = Ordering::Osa;
      } else if (t[1] == "nm") {
        ordering = Ordering::Nm;
      } else {
        r.fail(
            fmt::format("unknown ordering '{}': use osa (alias ansi: 'j c_um' lines, OSA/ANSI single index) or "
                        "nm ('n m c_um' lines); Noll and Fringe indices must be converted",
                        t[1]));
      }
    } else if (std::isdigit(static_cast<unsigned char>(key[0])) || key[0] == '-' || key[0] == '+') {
      if (ordering == Ordering::Unset)
        r.fail(fmt::format("coefficient line '{}' before an 'ordering' line (osa or nm)", line));
      const ZernikeIndex z = index_of(r, t, ordering);
      const int j = zernike_single_index(z.n, z.m);
      if (seen[j])
        r.fail(fmt::format("Zernike term j = {} (n {}, m {}) given again (first on line {})", j, z.n, z.m, seen[j]));
      seen[j] = r.line;
      const double c = r.number(t.back(), "coefficient");
      if (!(std::abs(c) <= kMaxZernikeCoefficient_um))
        r.fail(fmt::format("coefficient {} um of j = {} exceeds {} um in magnitude (units must be micrometres)",
                           t.back(), j, kMaxZernikeCoefficient_um));
      out.coefficients_um[j] = c;
      out.max_order = std::max(out.max_order, z.n);
    } else {
      r.fail(fmt::format("unknown key '{}' (expected pupil_diameter_mm, wavelength_nm, ordering or a coefficient line)",
                         key));
    }
  }
  if (!pupil_line)
    throw OpticsError(
        fmt::format("{}: no 'pupil_diameter_mm' line: the pupil the coefficients were measured over is "
                    "required",
                    origin));
  if (!ordering_line) throw OpticsError(fmt::format("{}: no 'ordering' line (osa or nm) and no coefficients", origin));
  bool any = false;
  for (int at : seen) any = any || at;
  if (!any) throw OpticsError(fmt::format("{}: no coefficient lines", origin));
  out.coefficients_um.resize(static_cast<size_t>(zernike_term_count(out.max_order)));
  return out;
}

ZernikeFile read_zernike_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw OpticsError(fmt::format("{}: cannot open the Zernike file", path));
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw OpticsError(fmt::format("{}: cannot read the Zernike file", path));
  return parse_zernike_text(text.str(), path);
}

}  // namespace eyetrace::optics
