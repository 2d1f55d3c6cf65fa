// libFuzzer target: PNG files (read_png_samples, the reader behind image textures and maps) and
// the MIP map built from what it accepts. An exception is the expected rejection; an accepted
// image holds no more samples than its bytes can encode, and every filtered lookup is finite.
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <string>

#include "render/image_library.h"
#include "render/mipmap.h"
#include "render/png_file.h"

namespace {

[[noreturn]] void violated(const char* what) {
  std::fprintf(stderr, "png_fuzzer: invariant violated: %s\n", what);
  std::abort();
}

void check_lookups(const eyetrace::MipMap& map) {
  using eyetrace::Vec2;
  for (eyetrace::MipFilter f : {eyetrace::MipFilter::Point, eyetrace::MipFilter::Bilinear,
                                eyetrace::MipFilter::Trilinear, eyetrace::MipFilter::Ewa})
    for (float d : {0.f, 0.01f, 0.3f}) {
      float out[3];
      map.filter(f, 8.f, Vec2(0.3f, 0.7f), Vec2(d, 0.f), Vec2(0.f, 0.5f * d), out);
      for (int c = 0; c < map.channels(); ++c)
        if (!std::isfinite(out[c])) violated("a lookup is not finite");
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  // libpng reads files: the input goes through one of this process's own.
  static const std::string path = "/tmp/eyetrace-png-fuzz-" + std::to_string(::getpid()) + ".png";
  std::ofstream(path, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(data), std::streamsize(size));
  try {
    eyetrace::ImageFileFormat format;
    eyetrace::PngSamples s = eyetrace::read_png_samples(path, &format);
    if (s.data.size() != size_t(s.width) * s.height * s.channels * (s.bit_depth / 8) ||
        double(s.data.size()) > 8.0 * 1032.0 * double(size) + double(1 << 20))
      violated("the samples do not match the header or exceed what the file can encode");
    const int n = s.channels >= 3 ? 3 : 1;
    const eyetrace::TexelEncoding srgb{eyetrace::TexelEncoding::Kind::SRGB, 1.f};
    if (s.bit_depth == 8) {
      check_lookups(
          eyetrace::MipMap(std::move(s.data), s.width, s.height, s.channels, n, srgb, eyetrace::MipWrap::Repeat));
    } else {
      check_lookups(eyetrace::MipMap(eyetrace::to_image(s), n, false, srgb, eyetrace::MipWrap::Black));
    }
  } catch (const std::exception&) {
  }
  return 0;
}
