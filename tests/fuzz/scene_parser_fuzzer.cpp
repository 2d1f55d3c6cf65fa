// libFuzzer target: the pbrt-v4 scene parser (parse_scene_string) on arbitrary bytes.
// A SceneError is the expected way to reject bad text; anything else that escapes (another
// exception, a crash, a sanitizer report, a hang) is a finding. A scene that parses must hold
// the invariants the scene builder relies on: finite transforms and valid references.
#include <sys/stat.h>

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "core/error.h"
#include "scene/parser.h"

namespace {

using eyetrace::SceneDescription;

// Include paths resolve here; an empty directory, so the fuzzer tests the parser, not the
// files lying around.
std::string g_search_dir;

[[noreturn]] void violated(const char* what) {
  std::fprintf(stderr, "scene_parser_fuzzer: invariant violated: %s\n", what);
  std::abort();
}

bool finite(const eyetrace::Transform& t) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(t.matrix()[c][r]) || !std::isfinite(t.inverse_matrix()[c][r])) return false;
  return true;
}

bool finite(const eyetrace::ParameterList& params) {
  for (const auto& p : params.params())
    for (double v : p.numbers)
      if (!std::isfinite(v)) return false;
  return true;
}

void check_shape(const SceneDescription& d, const eyetrace::ShapeEntity& s) {
  if (!finite(s.world_from_object) || !finite(s.params)) violated("non-finite shape transform or value");
  const auto& m = s.material;
  bool by_index = m.index >= 0 && size_t(m.index) < d.materials.size() && m.name.empty();
  // A name need not be defined yet: as in pbrt-v4, NamedMaterial may come before its
  // MakeNamedMaterial, and the scene builder reports a name never defined (named_material_test).
  bool by_name = m.index < 0 && !m.name.empty();
  if (!by_index && !by_name) violated("shape refers to a material that does not exist");
  if (s.area_light >= int(d.area_lights.size()) || s.area_light < -1) violated("bad area light index");
}

void check(const SceneDescription& d) {
  if (!finite(d.camera.world_from_camera)) violated("non-finite camera transform");
  for (const auto& s : d.shapes) check_shape(d, s);
  for (const auto& [name, def] : d.instances)
    for (const auto& s : def.shapes) check_shape(d, s);
  for (const auto& use : d.instance_uses) {
    if (d.instances.count(use.name) != 1) violated("instance use without a definition");
    if (!use.world_from_instance || !finite(*use.world_from_instance) || !finite(use.end_transform()))
      violated("non-finite or missing instance transform");
  }
  for (const auto& l : d.lights)
    if (!finite(l.world_from_object) || !finite(l.params)) violated("non-finite light");
  for (const auto& t : d.textures)
    if (!finite(t.world_from_object) || !finite(t.params)) violated("non-finite texture");
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  eyetrace::set_warnings_enabled(false);
  g_search_dir = "/tmp/eyetrace-fuzz-empty";
  if (mkdir(g_search_dir.c_str(), 0700) != 0 && errno != EEXIST) std::abort();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string_view text(reinterpret_cast<const char*>(data), size);
  // Include "/dev/stdin" or "/proc/..." would test the operating system, not the parser.
  for (std::string_view device : {"dev/", "proc/", "sys/"})
    if (text.find(device) != std::string_view::npos) return 0;
  try {
    check(eyetrace::parse_scene_string(text, "fuzz.pbrt", g_search_dir));
  } catch (const eyetrace::SceneError& e) {
    // Every message is complete: a location or "error:" first, then what went wrong.
    if (std::string_view(e.what()).find("error: ") == std::string_view::npos) violated("message without \"error: \"");
  }
  return 0;
}
