#include "render/render_state.h"

#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "core/error.h"
#include "core/fnv1a.h"

namespace eyetrace {

namespace fs = std::filesystem;

namespace {

constexpr std::string_view kRenderStateMagic = "EYETRACE-RENDER-STATE\n";

// Native byte order: a state file is for resuming on the machine (or kind of machine) that
// wrote it. The byte-order mark below makes any other reader refuse it instead of misreading.
constexpr uint32_t kByteOrderMark = 0x01020304;

class Writer {
 public:
  template <typename T>
  void put(const T& v) {
    bytes_.append(reinterpret_cast<const char*>(&v), sizeof v);
  }
  template <typename T>
  void put_array(const std::vector<T>& v) {
    put(uint64_t(v.size()));
    // An empty vector's data() may be null, which memcpy must never see (even for 0 bytes).
    if (!v.empty()) bytes_.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
  }
  std::string& bytes() { return bytes_; }

 private:
  std::string bytes_;
};

class Reader {
 public:
  Reader(const std::string& bytes, const std::string& path) : bytes_(bytes), path_(path) {}
  template <typename T>
  T get() {
    T v;
    need(sizeof v);
    std::memcpy(&v, bytes_.data() + pos_, sizeof v);
    pos_ += sizeof v;
    return v;
  }
  template <typename T>
  std::vector<T> get_array() {
    uint64_t n = get<uint64_t>();
    if (n > (bytes_.size() - pos_) / sizeof(T)) corrupt("an array is longer than the file");
    std::vector<T> v(n);
    if (n > 0) std::memcpy(v.data(), bytes_.data() + pos_, n * sizeof(T));  // data() of an empty vector may be null
    pos_ += n * sizeof(T);
    return v;
  }
  size_t position() const { return pos_; }
  [[noreturn]] void corrupt(const std::string& why) const {
    throw_error(fmt::format("render state \"{}\": {} (the file is damaged; render without --resume)", path_, why));
  }

 private:
  void need(size_t n) const {
    if (bytes_.size() - pos_ < n) corrupt("it ends early");
  }
  const std::string& bytes_;
  const std::string& path_;
  size_t pos_ = 0;
};

}  // namespace

void write_render_state(const std::string& path, const RenderState& s) {
  Writer w;
  w.bytes().append(kRenderStateMagic);
  w.put(kByteOrderMark);
  w.put(RenderState::kVersion);
  w.put(s.fingerprint);
  for (int v : {s.resolution.x, s.resolution.y, s.bounds.lo.x, s.bounds.lo.y, s.bounds.hi.x, s.bounds.hi.y,
                s.samples_per_pixel, TileProgress::kTileSize, s.tiles.tiles.x, s.tiles.tiles.y, s.spectral_buckets})
    w.put(int32_t(v));
  w.put_array(s.tiles.done);
  w.put_array(s.tiles.pixel_done);
  w.put_array(s.tiles.pixel_target);
  w.put(s.nonfinite_samples);
  w.put_array(s.accumulators);
  w.put(fnv1a(w.bytes()));

  fs::path target(path);
  fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  fs::path tmp = dir / fmt::format(".{}.tmp{:08x}", target.filename().string(), std::random_device()());
  {
    std::ofstream out(tmp, std::ios::binary);
    out.write(w.bytes().data(), std::streamsize(w.bytes().size()));
    out.close();
    if (!out) {
      std::error_code ec;
      fs::remove(tmp, ec);
      throw_error(fmt::format("render state \"{}\": cannot write", path));
    }
  }
  std::error_code ec;
  fs::rename(tmp, target, ec);
  if (ec) {
    fs::remove(tmp, ec);
    throw_error(fmt::format("render state \"{}\": cannot move it into place", path));
  }
}

RenderState read_render_state(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw_error(
        fmt::format("render state \"{}\" not found: --resume needs the state an interrupted or "
                    "checkpointed render leaves next to its output",
                    path));
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  Reader r(bytes, path);
  if (bytes.compare(0, kRenderStateMagic.size(), kRenderStateMagic) != 0) r.corrupt("not an eyetrace render state");
  if (bytes.size() < kRenderStateMagic.size() + 8 + 8) r.corrupt("it ends early");
  uint64_t stored_sum;
  std::memcpy(&stored_sum, bytes.data() + bytes.size() - 8, 8);
  if (fnv1a(std::string_view(bytes).substr(0, bytes.size() - 8)) != stored_sum)
    r.corrupt("its checksum does not match");
  for (size_t i = 0; i < kRenderStateMagic.size(); ++i) r.get<char>();
  if (r.get<uint32_t>() != kByteOrderMark) r.corrupt("it was written on a machine of another byte order");
  uint32_t version = r.get<uint32_t>();
  if (version != RenderState::kVersion)
    r.corrupt(fmt::format("format version {}, this eyetrace reads version {}", version, RenderState::kVersion));
  RenderState s;
  s.fingerprint = r.get<uint64_t>();
  int32_t v[11];
  for (int32_t& x : v) x = r.get<int32_t>();
  s.resolution = IVec2(v[0], v[1]);
  s.bounds = PixelBounds{IVec2(v[2], v[3]), IVec2(v[4], v[5])};
  s.samples_per_pixel = v[6];
  if (v[7] != TileProgress::kTileSize) r.corrupt("it was written with another tile size");
  s.tiles.tiles = IVec2(v[8], v[9]);
  s.spectral_buckets = v[10];
  if (s.spectral_buckets < 0 || s.spectral_buckets > SpectralBuckets::kMaxCount)
    r.corrupt(
        fmt::format("its spectral bucket count {} is outside [0, {}]", s.spectral_buckets, SpectralBuckets::kMaxCount));
  s.tiles.done = r.get_array<int>();
  s.tiles.pixel_done = r.get_array<int>();
  s.tiles.pixel_target = r.get_array<int>();
  s.nonfinite_samples = r.get<uint64_t>();
  s.accumulators = r.get_array<double>();
  if (r.position() + 8 != bytes.size()) r.corrupt("it has trailing bytes");
  bool sane = s.bounds.lo.x >= 0 && s.bounds.lo.y >= 0 && s.bounds.hi.x > s.bounds.lo.x &&
              s.bounds.hi.y > s.bounds.lo.y && s.tiles.matches(s.bounds) &&
              s.accumulators.size() == s.bounds.area() * (Film::kAccumulatorsPerPixel +
                                                          Film::kBucketAccumulators * size_t(s.spectral_buckets));
  if (!sane) r.corrupt("its film and tile sizes disagree");
  for (int d : s.tiles.done)
    if (d < 0 || d > s.samples_per_pixel) r.corrupt("a tile count is outside [0, samples per pixel]");
  const size_t adaptive = s.tiles.pixel_done.size();
  if ((adaptive != 0 && adaptive != s.bounds.area()) || s.tiles.pixel_target.size() != adaptive)
    r.corrupt("its per-pixel sample counts do not match the film");
  for (size_t i = 0; i < adaptive; ++i)
    if (s.tiles.pixel_done[i] < 0 || s.tiles.pixel_done[i] > s.tiles.pixel_target[i] ||
        s.tiles.pixel_target[i] > s.samples_per_pixel)
      r.corrupt("a pixel's sample count is outside [0, its target <= samples per pixel]");
  return s;
}

}  // namespace eyetrace
