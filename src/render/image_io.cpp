#include "render/image_io.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>

#include "core/error.h"

namespace eyetrace {

namespace fs = std::filesystem;

float linear_to_srgb(float v) {
  if (!(v > 0.f)) return 0.f;
  return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.f / 2.4f) - 0.055f;
}

float srgb_to_linear(float v) { return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f); }

// EXR compression: lossless run-length. Rendered pixels carry noise in their low mantissa bits,
// which no lossless coder removes: on the figure renders zip saves 3.5 % of the raw size and
// RLE 0.3 %, on mostly black images (the chromatic figure) zip 89 % and RLE 88 %; but zip
// writes a 4096x4096 film (200 MB) in about 2.4 s on two cores, RLE in 0.4 s (issue 17's
// "reduction and output under 1 s"). Measured in docs/cluster.md.
constexpr const char* kExrCompression = "rle";

static std::string lower_extension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

void write_image(const std::string& path, const Image& image, const std::map<std::string, std::string>& metadata) {
  std::string ext = lower_extension(path);
  bool is_float = ext == ".exr" || ext == ".hdr" || ext == ".pfm";
  if (!is_float && ext != ".png" && ext != ".jpg" && ext != ".jpeg" && ext != ".tif" && ext != ".tiff")
    throw_error(fmt::format("output \"{}\": unsupported image extension \"{}\" (use .exr or .png)", path, ext));
  if (!is_float && image.channels != 3)
    throw_error(fmt::format("output \"{}\": a {}-channel image (a spectral film's) can only be written as .exr", path,
                            image.channels));
  if (!image.channel_names.empty() && int(image.channel_names.size()) != image.channels)
    throw_error(fmt::format("output \"{}\": {} channel names for {} channels", path, image.channel_names.size(),
                            image.channels));
  fs::path target(path);
  fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  std::error_code ec;
  fs::create_directories(dir, ec);
  // The temporary keeps the real extension so OIIO picks the right writer.
  std::random_device rd;
  fs::path tmp = dir / fmt::format(".{}.tmp{:08x}{}", target.stem().string(), rd(), ext);

  OIIO::ImageSpec spec(image.width, image.height, image.channels,
                       is_float ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
  if (!image.channel_names.empty()) spec.channelnames = image.channel_names;
  for (const auto& [k, v] : metadata) spec.attribute(k, v);
  // 8-bit output converts a copy; float output writes the pixels as they are (a 4096x4096
  // film's are 200 MB: no copy).
  std::vector<float> encoded;
  if (!is_float) {
    spec.attribute("oiio:ColorSpace", "sRGB");
    encoded.resize(image.pixels.size());
    for (size_t i = 0; i < encoded.size(); ++i)
      encoded[i] = std::clamp(linear_to_srgb(std::isfinite(image.pixels[i]) ? image.pixels[i] : 0.f), 0.f, 1.f);
  } else {
    spec.attribute("compression", kExrCompression);
  }
  const float* pixels = is_float ? image.pixels.data() : encoded.data();
  auto out = OIIO::ImageOutput::create(tmp.string());
  if (!out) throw_error(fmt::format("output \"{}\": cannot create a writer: {}", path, OIIO::geterror()));
  bool ok = out->open(tmp.string(), spec) && out->write_image(OIIO::TypeDesc::FLOAT, pixels) && out->close();
  if (!ok) {
    std::string err = out->geterror();
    fs::remove(tmp, ec);
    throw_error(fmt::format("output \"{}\": write failed: {}", path, err));
  }
  fs::rename(tmp, target, ec);
  if (ec) {
    fs::remove(tmp, ec);
    throw_error(fmt::format("output \"{}\": cannot move the finished image into place", path));
  }
}

Image read_image(const std::string& path) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) throw_error(fmt::format("image \"{}\": cannot read: {}", path, OIIO::geterror()));
  const OIIO::ImageSpec& spec = in->spec();
  Image img;
  img.width = spec.width;
  img.height = spec.height;
  img.channels = spec.nchannels;
  img.channel_names = spec.channelnames;
  img.pixels.resize(size_t(img.width) * img.height * img.channels);
  if (!in->read_image(0, 0, 0, img.channels, OIIO::TypeDesc::FLOAT, img.pixels.data()))
    throw_error(fmt::format("image \"{}\": read failed: {}", path, in->geterror()));
  in->close();
  return img;
}

std::string read_image_attribute(const std::string& path, const std::string& name) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) return "";
  std::string v = in->spec().get_string_attribute(name);
  in->close();
  return v;
}

}  // namespace eyetrace
