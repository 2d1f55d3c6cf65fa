// libFuzzer target: the gzip include reader. Each input is written as a file that a scene
// Includes ("fuzz.pbrt.gz"), so the whole path is exercised: the file read, the gzip check,
// zlib's inflate with its CRC and length checks, and the inflated text spliced into the
// including scene's tokens. A SceneError is the expected rejection, and it must name the
// included file when the gzip data is bad; anything else escaping is a finding.
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <string_view>

#include "core/error.h"
#include "core/gzip.h"
#include "scene/parser.h"

namespace {

std::string g_dir;

[[noreturn]] void violated(const char* what) {
  std::fprintf(stderr, "gzip_include_fuzzer: invariant violated: %s\n", what);
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  eyetrace::set_warnings_enabled(false);
  g_dir = "/tmp/eyetrace-fuzz-gzip-" + std::to_string(getpid());
  if (mkdir(g_dir.c_str(), 0700) != 0 && errno != EEXIST) std::abort();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  const std::string included = g_dir + "/fuzz.pbrt.gz";
  {
    std::ofstream out(included, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), std::streamsize(bytes.size()));
    if (!out) std::abort();
  }
  // The inflated text as the reader sees it, to know which outcome to expect.
  std::string error;
  const bool gz = eyetrace::is_gzip(bytes);
  const bool inflates = gz && eyetrace::gunzip(bytes, &error).has_value();
  if (gz && !inflates && error.empty()) violated("gunzip failed without saying why");
  try {
    eyetrace::parse_scene_string("WorldBegin\nInclude \"fuzz.pbrt.gz\"\n", "main.pbrt", g_dir);
  } catch (const eyetrace::SceneError& e) {
    const std::string_view what = e.what();
    if (what.find("error: ") == std::string_view::npos) violated("message without \"error: \"");
    if (gz && !inflates && what.find("fuzz.pbrt.gz\": gzip-compressed file: ") == std::string_view::npos)
      violated("bad gzip data reported without naming the file");
  }
  return 0;
}
