#include "render/exr_file.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfThreading.h>
#include <OpenEXR/ImfVersion.h>

#include <algorithm>
#include <cctype>
#include <ctime>
#include <fstream>
#include <mutex>
#include <numeric>
#include <span>
#include <stdexcept>
#include <thread>

#include <fmt/core.h>

namespace eyetrace {

namespace {

// OpenImageIO's name for the capture date is DateTime; OpenEXR's is capDate.
constexpr const char* kDateAttribute = "capDate";

// EXR compression: lossless run-length. Rendered pixels carry noise in their low mantissa bits,
// which no lossless coder removes: on the figure renders zip saves 3.5 % of the raw size and
// RLE 0.3 %, on mostly black images (the chromatic figure) zip 89 % and RLE 88 %; but zip
// writes a 4096x4096 film (200 MB) in about 2.4 s on two cores, RLE in 0.4 s (issue 17's
// "reduction and output under 1 s"). Measured in docs/cluster.md.
constexpr Imf::Compression kCompression = Imf::RLE_COMPRESSION;

// OpenEXR compresses and decompresses blocks of scan lines on its own thread pool; OpenImageIO
// gave it one thread per core, and so do we (once, at the first EXR read or write).
void use_all_cores() {
  static std::once_flag once;
  std::call_once(once, [] { Imf::setGlobalThreadCount(int(std::max(1u, std::thread::hardware_concurrency()))); });
}

std::string now_as_exif_date() {
  std::time_t t = std::time(nullptr);
  std::tm local{};
  localtime_r(&t, &local);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y:%m:%d %H:%M:%S", &local);
  return buf;
}

bool iequals(const std::string& a, const char* b) {
  size_t n = std::char_traits<char>::length(b);
  if (a.size() != n) return false;
  for (size_t i = 0; i < n; ++i)
    if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) return false;
  return true;
}

// The names OpenImageIO 2.4's EXR reader puts first within a layer, in this order; a layer with
// an X and a Y or Z channel (a position or a normal) uses the second list.
int special_index(const std::string& suffix, bool xyz) {
  static const char* const usual[] = {"R",     "Red", "G",  "Green", "B",  "Blue", "Y",  "real", "imag",  "A",
                                      "Alpha", "AR",  "RA", "AG",    "GA", "AB",   "BA", "Z",    "Depth", "Zback"};
  static const char* const vector[] = {"R", "Red",   "G",  "Green", "B",  "Blue", "X",  "Y",  "Z",     "real", "imag",
                                       "A", "Alpha", "AR", "RA",    "AG", "GA",   "AB", "BA", "Depth", "Zback"};
  const std::span<const char* const> list =
      xyz ? std::span<const char* const>(vector) : std::span<const char* const>(usual);
  for (int i = 0; i < int(list.size()); ++i)
    if (iequals(suffix, list[i])) return i;
  return 10000;
}

}  // namespace

std::vector<int> oiio_channel_order(const std::vector<std::string>& names) {
  struct Key {
    std::string layer, suffix;  // layer keeps its trailing '.'
    int special = 10000;
  };
  std::vector<Key> keys;
  for (const std::string& n : names) {
    size_t dot = n.find_last_of('.');
    if (dot == std::string::npos)
      keys.push_back({"", n});
    else
      keys.push_back({n.substr(0, dot + 1), n.substr(dot + 1)});
  }
  // Within each layer: the vector list when it has X and Y or Z, else the usual one.
  for (Key& k : keys) {
    auto in_layer = [&](const char* s) {
      for (const Key& o : keys)
        if (o.layer == k.layer && iequals(o.suffix, s)) return true;
      return false;
    };
    k.special = special_index(k.suffix, in_layer("X") && (in_layer("Y") || in_layer("Z")));
  }
  std::vector<int> order(names.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    if (keys[a].layer != keys[b].layer) return keys[a].layer < keys[b].layer;
    if (keys[a].special != keys[b].special) return keys[a].special < keys[b].special;
    return keys[a].suffix < keys[b].suffix;
  });
  return order;
}

bool is_exr_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  char magic[4] = {};
  return in.read(magic, 4) && Imf::isImfMagic(magic);
}

void write_exr(const std::string& path, const Image& image, const std::map<std::string, std::string>& metadata) {
  use_all_cores();
  Imf::Header header(image.width, image.height);
  header.compression() = kCompression;
  const int nc = image.channels;
  std::vector<std::string> names = image.channel_names;
  if (names.empty()) names = {"R", "G", "B"};
  bool has_date = false;
  for (const auto& [k, v] : metadata) {
    bool date = k == "DateTime" || k == kDateAttribute;
    has_date |= date;
    header.insert(date ? kDateAttribute : k, Imf::StringAttribute(v));
  }
  if (!has_date) header.insert(kDateAttribute, Imf::StringAttribute(now_as_exif_date()));

  Imf::FrameBuffer fb;
  const size_t xstride = sizeof(float) * nc, ystride = xstride * size_t(image.width);
  auto* base = reinterpret_cast<char*>(const_cast<float*>(image.pixels.data()));
  for (int c = 0; c < nc; ++c) {
    header.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
    fb.insert(names[c], Imf::Slice(Imf::FLOAT, base + c * sizeof(float), xstride, ystride));
  }
  Imf::OutputFile out(path.c_str(), header);
  out.setFrameBuffer(fb);
  out.writePixels(image.height);
}

Image read_exr(const std::string& path) {
  use_all_cores();
  Imf::InputFile in(path.c_str());
  const Imf::Header& h = in.header();
  const Imath::Box2i dw = h.dataWindow();
  Image img;
  img.width = dw.max.x - dw.min.x + 1;
  img.height = dw.max.y - dw.min.y + 1;
  std::vector<std::string> stored;
  for (auto it = h.channels().begin(); it != h.channels().end(); ++it) {
    if (it.channel().xSampling != 1 || it.channel().ySampling != 1)
      throw std::runtime_error(fmt::format("channel \"{}\" is subsampled, which eyetrace does not read", it.name()));
    stored.push_back(it.name());
  }
  if (img.width <= 0 || img.height <= 0 || stored.empty()) throw std::runtime_error("the image is empty");
  img.channels = int(stored.size());
  for (int i : oiio_channel_order(stored)) img.channel_names.push_back(stored[i]);
  img.pixels.assign(size_t(img.width) * img.height * img.channels, 0.f);

  // The slices address pixel (x, y) of the data window at pixels[((y - min.y) w + x - min.x) nc + c].
  Imf::FrameBuffer fb;
  const size_t xstride = sizeof(float) * img.channels, ystride = xstride * size_t(img.width);
  char* origin = reinterpret_cast<char*>(img.pixels.data()) - ptrdiff_t(dw.min.x) * ptrdiff_t(xstride) -
                 ptrdiff_t(dw.min.y) * ptrdiff_t(ystride);
  for (int c = 0; c < img.channels; ++c)
    fb.insert(img.channel_names[c], Imf::Slice(Imf::FLOAT, origin + c * sizeof(float), xstride, ystride));
  in.setFrameBuffer(fb);
  in.readPixels(dw.min.y, dw.max.y);
  return img;
}

std::string read_exr_attribute(const std::string& path, const std::string& name) {
  try {
    Imf::InputFile in(path.c_str());
    const auto* a = in.header().findTypedAttribute<Imf::StringAttribute>(name == "DateTime" ? kDateAttribute : name);
    return a ? a->value() : "";
  } catch (const std::exception&) {
    return "";
  }
}

}  // namespace eyetrace
