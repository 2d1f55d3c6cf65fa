#include "scene/spectrum_file.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/error.h"
#include "scene/scene_files.h"
#include "scene/tokenizer.h"

namespace eyetrace {

namespace {

struct Number {
  double value;
  int line;
};

// Every number of the text; `bad` gets the first word that is not one (and its line).
std::vector<Number> numbers_of(const std::string& text, std::string* bad, int* bad_line) {
  std::vector<Number> out;
  std::istringstream lines(text);
  std::string line;
  for (int n = 1; std::getline(lines, line); ++n) {
    line = line.substr(0, line.find('#'));
    for (char& c : line)
      if (c == ',') c = ' ';
    std::istringstream words(line);
    std::string w;
    while (words >> w) {
      double v = 0;
      if (parse_number(w, &v) != NumberStatus::Ok) {
        *bad = w;
        *bad_line = n;
        return out;
      }
      out.push_back({v, n});
    }
  }
  return out;
}

}  // namespace

std::string spectrum_file_path(const std::string& search_dir, const std::string& name) {
  return resolve_scene_file(search_dir, name);
}

std::vector<double> read_spectrum_file(const std::string& search_dir, const std::string& name, const SourceLoc& at,
                                       const std::string& parameter) {
  const std::string path = resolve_scene_file(search_dir, name);
  auto fail_file = [&](const std::string& why) {
    throw_parameter_error(at, parameter,
                          fmt::format("parameter \"{}\": spectrum file \"{}\": {}", parameter, path, why));
  };
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw_missing_file(at, parameter, fmt::format("parameter \"{}\": spectrum file \"{}\" not found", parameter, path));
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  if (!in) fail_file("cannot read it");
  std::string bad;
  int bad_line = 0;
  const std::vector<Number> v = numbers_of(text.str(), &bad, &bad_line);
  if (!bad.empty()) fail_file(fmt::format("line {}: \"{}\" is not a finite number", bad_line, bad.substr(0, 40)));
  if (v.size() < 4 || v.size() % 2 != 0)
    fail_file(fmt::format("needs (wavelength, value) pairs, at least two; it has {} number{}", v.size(),
                          v.size() == 1 ? "" : "s"));
  std::vector<double> pairs;
  for (size_t i = 0; i < v.size(); i += 2) {
    if (v[i].value <= 0.0 || (i > 0 && v[i].value <= v[i - 2].value))
      fail_file(fmt::format("line {}: wavelengths must be positive and increasing (got {} nm)", v[i].line, v[i].value));
    if (std::abs(v[i + 1].value) > 3.0e38)
      fail_file(fmt::format("line {}: value {} is beyond the float range", v[i + 1].line, v[i + 1].value));
    pairs.push_back(v[i].value);
    pairs.push_back(v[i + 1].value);
  }
  return pairs;
}

}  // namespace eyetrace
