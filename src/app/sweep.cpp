// The sweep file (docs/sweeps.md): JSON read, every key and camera parameter checked, and the
// cartesian product of the varied values expanded into jobs with stable, filesystem-safe names.
#include "app/sweep.h"

#include <fmt/core.h>
#include <stdlib.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>

#include "core/error.h"
#include "scene/parser.h"
#include "scene/registry.h"
#include "scene/scene_builder.h"
#include "scene/scene_fingerprint.h"

namespace eyetrace {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// The options besides camera parameters that a sweep may fix (a value) or vary (a list).
const std::vector<std::string> kRenderKeys = {"spp", "resolution", "seed"};
const std::vector<std::string> kKeys = {"scene", "camera", "output", "format", "vary", "spp", "resolution", "seed"};

[[noreturn]] void fail(const std::string& file, const std::string& message) {
  throw std::runtime_error(fmt::format("{}: {}", file, message));
}

json read_json(const std::string& path) {
  std::ifstream f(path);
  if (!f) fail(path, "cannot read the sweep file");
  std::stringstream text;
  text << f.rdbuf();
  try {
    return json::parse(text.str());
  } catch (const json::parse_error& e) {
    // nlohmann's message names the line and column ("at line 3, column 5").
    fail(path, fmt::format("not valid JSON: {}", e.what()));
  }
}

// One varied (or fixed) dimension: a camera parameter "float pupildiameter" or an option "spp".
struct Dimension {
  std::string key;    // as written in the file
  std::string label;  // the parameter's name: the CSV column and the output name's part
  std::string type;   // "float", "integer", "bool", "string"; "" for an option
  std::vector<json> values;
};

std::string value_text(const json& v) { return v.is_string() ? v.get<std::string>() : v.dump(); }

// Filesystem-safe and stable: letters, digits, '.', '+' and '-' kept, anything else '_'.
std::string safe(const std::string& s) {
  std::string r;
  for (char c : s) r += std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '+' || c == '-' ? c : '_';
  return r;
}

void check_option_value(const std::string& file, const std::string& key, const json& v) {
  static const std::regex wxh("[1-9][0-9]{0,4}x[1-9][0-9]{0,4}");
  bool ok = key == "resolution" ? v.is_string() && std::regex_match(v.get<std::string>(), wxh)
            : key == "spp"      ? v.is_number_integer() && v.get<int64_t>() >= 1 && v.get<int64_t>() <= (1 << 24)
                                : v.is_number_integer() && v.get<int64_t>() >= 0;
  if (!ok)
    fail(file, fmt::format("\"{}\": {} is not {}", key, v.dump(),
                           key == "resolution" ? "a string \"WxH\""
                           : key == "spp"      ? "an integer from 1 to 16777216"
                                               : "a non-negative integer"));
}

void check_camera_value(const std::string& file, const Dimension& d, const json& v) {
  bool ok = d.type == "float"     ? v.is_number()
            : d.type == "integer" ? v.is_number_integer()
            : d.type == "bool"    ? v.is_boolean()
                                  : v.is_string() && v.get<std::string>().find('"') == std::string::npos;
  if (!ok) fail(file, fmt::format("vary: \"{}\": {} is not a {} value", d.key, v.dump(), d.type));
}

// "float pupildiameter" -> a dimension, checked against the camera's declared parameters.
Dimension camera_dimension(const std::string& file, const std::string& key, const SceneEntity& camera) {
  std::istringstream words(key);
  Dimension d;
  d.key = key;
  std::string extra;
  if (!(words >> d.type >> d.label) || (words >> extra))
    fail(file, fmt::format("vary: \"{}\": expected a typed camera parameter such as \"float pupildiameter\"", key));
  const auto* entry = Registry::builtin().cameras.find(camera.name);
  const ParamSpec* spec = entry->spec->find(d.label);
  if (!spec) {
    std::vector<std::string> names;
    for (const ParamSpec& p : entry->spec->params) names.push_back(p.name);
    std::string hint = closest_match(d.label, names);
    fail(file, fmt::format("vary: \"{}\": camera \"{}\" has no parameter \"{}\"{}", key, camera.name, d.label,
                           hint.empty() ? "" : fmt::format(" (did you mean \"{}\"?)", hint)));
  }
  const std::vector<std::string> types = spec->accepted_types();
  if (std::find(types.begin(), types.end(), d.type) == types.end())
    fail(file, fmt::format("vary: \"{}\": camera \"{}\" parameter \"{}\" is a {}", key, camera.name, d.label,
                           spec->type_name()));
  if (d.type != "float" && d.type != "integer" && d.type != "bool" && d.type != "string")
    fail(file, fmt::format("vary: \"{}\": only float, integer, bool and string parameters can be varied", key));
  if (camera.params.has(d.label))
    fail(file, fmt::format("vary: \"{}\" is also set in \"camera\"; give it in one place", key));
  return d;
}

std::vector<json> as_list(const std::string& file, const std::string& key, const json& v) {
  if (!v.is_array()) return {v};
  if (v.empty()) fail(file, fmt::format("\"{}\": an empty list of values", key));
  return std::vector<json>(v.begin(), v.end());
}

void check_keys(const std::string& file, const json& j) {
  if (!j.is_object()) fail(file, "expected a JSON object of sweep settings");
  for (const auto& [key, value] : j.items())
    if (std::find(kKeys.begin(), kKeys.end(), key) == kKeys.end()) {
      std::string hint = closest_match(key, kKeys);
      fail(file, fmt::format("unknown key \"{}\"{}; a sweep file has: scene, camera, output, format, vary, spp, "
                             "resolution, seed",
                             key, hint.empty() ? "" : fmt::format(" (did you mean \"{}\"?)", hint)));
    }
  for (const char* key : {"scene", "camera", "output"})
    if (!j.contains(key) || !j[key].is_string()) fail(file, fmt::format("\"{}\": required, a string", key));
  if (j.contains("format") && j["format"] != "exr" && j["format"] != "png")
    fail(file, "\"format\": \"exr\" (linear float, the default) or \"png\" (sRGB 8-bit)");
  if (j.contains("vary") && !j["vary"].is_object())
    fail(file, "\"vary\": expected an object: camera parameter -> list of values");
}

std::string resolve(const std::string& file, const std::string& path) {
  fs::path p(path);
  return p.is_absolute() ? path : (fs::path(file).parent_path() / p).lexically_normal().string();
}

// Creates the folder and proves it writable by making (and removing) a file in it.
void check_output_dir(const std::string& file, const std::string& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir))
    fail(file, fmt::format("output folder \"{}\" cannot be created: {}", dir, ec ? ec.message() : "not a folder"));
  std::string probe = (fs::path(dir) / ".sweep-write-test-XXXXXX").string();
  int fd = mkstemp(probe.data());
  if (fd < 0) fail(file, fmt::format("output folder \"{}\" cannot be written", dir));
  close(fd);
  fs::remove(probe, ec);
}

std::vector<Dimension> dimensions(const std::string& file, const json& j, const SceneEntity& camera) {
  std::vector<Dimension> dims;
  if (j.contains("vary"))
    for (const auto& [key, values] : j["vary"].items()) {
      Dimension d = camera_dimension(file, key, camera);
      if (!values.is_array()) fail(file, fmt::format("vary: \"{}\": expected a list of values", key));
      d.values = as_list(file, "vary: " + key, values);
      for (const json& v : d.values) check_camera_value(file, d, v);
      dims.push_back(std::move(d));
    }
  for (const std::string& key : kRenderKeys)
    if (j.contains(key)) {
      Dimension d{key, key, "", as_list(file, key, j[key])};
      for (const json& v : d.values) check_option_value(file, key, v);
      dims.push_back(std::move(d));
    }
  std::sort(dims.begin(), dims.end(), [](const Dimension& a, const Dimension& b) { return a.label < b.label; });
  for (size_t i = 1; i < dims.size(); ++i)
    if (dims[i].label == dims[i - 1].label)
      fail(file, fmt::format("\"{}\" and \"{}\" name the same parameter", dims[i - 1].key, dims[i].key));
  return dims;
}

// Sets job option or camera parameter `d` to `v`.
void apply(const Dimension& d, const json& v, SweepJob& job) {
  if (d.label == "spp" && d.type.empty())
    job.spp = v.get<int>();
  else if (d.label == "seed" && d.type.empty())
    job.seed = v.get<int64_t>();
  else if (d.label == "resolution" && d.type.empty())
    job.resolution = v.get<std::string>();
  else
    job.camera += fmt::format(" \"{} {}\" [ {} ]", d.type, d.label,
                              v.is_string() ? "\"" + v.get<std::string>() + "\"" : v.dump());
}

std::vector<SweepJob> expand(const std::vector<Dimension>& dims, const std::string& camera, const std::string& dir,
                             const std::string& format) {
  size_t count = 1;
  for (const Dimension& d : dims) count *= d.values.size();
  std::vector<SweepJob> jobs;
  for (size_t index = 0; index < count; ++index) {
    SweepJob job;
    job.camera = camera;
    size_t rest = index;
    std::vector<size_t> pick(dims.size());
    for (size_t k = dims.size(); k-- > 0;) {  // the last dimension varies fastest
      pick[k] = rest % dims[k].values.size();
      rest /= dims[k].values.size();
    }
    for (size_t k = 0; k < dims.size(); ++k) {
      const json& v = dims[k].values[pick[k]];
      apply(dims[k], v, job);
      if (dims[k].values.size() > 1) {
        job.values.emplace_back(dims[k].label, value_text(v));
        job.name += (job.name.empty() ? "" : "_") + dims[k].label + "-" + safe(value_text(v));
      }
    }
    if (job.name.empty()) job.name = "render";
    const fs::path stem = fs::path(dir) / job.name;
    job.output = stem.string() + "." + format;
    job.stats = stem.string() + ".json";
    job.log = stem.string() + ".log";
    jobs.push_back(std::move(job));
  }
  return jobs;
}

}  // namespace

std::vector<std::string> SweepJob::render_args(const std::string& scene, const std::string& stats_path,
                                               int threads) const {
  std::vector<std::string> a = {"render", scene, "--camera", camera, "-o", output, "--stats", stats_path, "--quiet"};
  if (spp > 0) a.insert(a.end(), {"--spp", std::to_string(spp)});
  if (!resolution.empty()) a.insert(a.end(), {"--resolution", resolution});
  if (seed >= 0) a.insert(a.end(), {"--seed", std::to_string(seed)});
  if (threads > 0) a.insert(a.end(), {"--threads", std::to_string(threads)});
  return a;
}

Sweep read_sweep(const std::string& path) {
  const json j = read_json(path);
  check_keys(path, j);
  Sweep s;
  s.file = path;
  s.scene = resolve(path, j["scene"].get<std::string>());
  s.output_dir = resolve(path, j["output"].get<std::string>());
  const std::string camera = j["camera"].get<std::string>();
  const SceneEntity base = parse_directive_text(camera, "Camera", path + ": camera");
  Registry::builtin().cameras.at(base.name, base.loc);  // an unknown camera: "did you mean"
  const std::vector<Dimension> dims = dimensions(path, j, base);
  for (const Dimension& d : dims)
    if (d.values.size() > 1) s.varied.push_back(d.label);
  const SceneDescription desc = parse_scene_file(s.scene);
  RenderOverrides base_overrides;
  base_overrides.camera = base;
  build_camera(desc, base_overrides);  // the fixed part of the camera, checked once
  check_output_dir(path, s.output_dir);
  s.table = (fs::path(s.output_dir) / fs::path(path).stem()).string() + ".csv";
  s.jobs = expand(dims, camera, s.output_dir, j.value("format", "exr"));
  std::set<std::string> names;
  for (SweepJob& job : s.jobs) {
    if (!names.insert(job.name).second)
      fail(path, fmt::format("two jobs would both write \"{}\" (values that differ only in characters a file name "
                             "cannot hold)",
                             job.output));
    // What decides the image: the scene as parsed and every option but where it is written.
    job.key = scene_fingerprint(desc, fmt::format("{}|{}|{}|{}", job.camera, job.spp, job.resolution, job.seed), {});
  }
  return s;
}

}  // namespace eyetrace
