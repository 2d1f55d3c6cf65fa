#include "textures/imagemap_texture.h"

#include <cmath>
#include <filesystem>

#include "render/image_io.h"
#include "render/image_library.h"
#include "render/mipmap.h"
#include "render/png_file.h"
#include "scene/scene_files.h"
#include "scene/texture_store.h"
#include "textures/texture_mapping.h"

namespace eyetrace {

namespace {

// Everything an image lookup needs, shared by the float and spectrum variants.
struct ImageLookup {
  const MipMap* map = nullptr;  // owned by the scene's TextureStore
  MipFilter filter = MipFilter::Bilinear;
  float max_anisotropy = 8.f;
  float scale = 1.f;
  bool invert = false;
  TextureMapping2D mapping;

  // The channels at the hit (1 or 3), filtered, scaled and inverted; returns how many.
  int fetch(const TextureEvalContext& ctx, float out[3]) const {
    TextureCoords c = mapping.map(ctx);
    // pbrt-v4 flips t so that t = 0 is the image's top row; the footprint is square.
    map->filter(filter, max_anisotropy, Vec2(c.st.x, 1.f - c.st.y), Vec2(c.width, 0.f), Vec2(0.f, c.width), out);
    const int n = map->channels();
    for (int i = 0; i < n; ++i) out[i] = finish(out[i]);
    return n;
  }

  float finish(float v) const {
    v *= scale;
    if (invert) v = std::max(0.f, 1.f - v);
    return std::isfinite(v) ? v : 0.f;
  }
};

MipFilter read_filter(const PluginParams& p) {
  const std::string filter = p.get_string("filter");  // one of the declared choices
  return filter == "point"       ? MipFilter::Point
         : filter == "bilinear"  ? MipFilter::Bilinear
         : filter == "trilinear" ? MipFilter::Trilinear
                                 : MipFilter::Ewa;  // ewa, EWA
}

MipWrap read_wrap(const PluginParams& p) {
  const std::string wrap = p.get_string("wrap");
  return wrap == "black" ? MipWrap::Black : wrap == "clamp" ? MipWrap::Clamp : MipWrap::Repeat;
}

TexelEncoding read_encoding(const PluginParams& p, const std::string& path, const ImageFileFormat& format) {
  // Floating-point pixels are linear already (pbrt-v4 ignores the encoding for them).
  if (!format.integer) return {};
  std::string ext = std::filesystem::path(path).extension().string();
  for (auto& ch : ext) ch = char(std::tolower(static_cast<unsigned char>(ch)));
  std::string e = p.has("encoding") ? p.get_string("encoding") : ext == ".png" || format.eight_bit ? "sRGB" : "linear";
  if (e == "sRGB" || e == "srgb") return {TexelEncoding::Kind::SRGB, 1.f};
  if (e == "linear") return {};
  if (e.rfind("gamma ", 0) == 0) {
    char* end = nullptr;
    float g = std::strtof(e.c_str() + 6, &end);
    if (!(g > 0.f) || !std::isfinite(g) || (end && *end != '\0'))
      p.fail("encoding", fmt::format("bad gamma in \"{}\"", e));
    return {TexelEncoding::Kind::Gamma, g};
  }
  p.fail("encoding", fmt::format("unknown encoding \"{}\"; eyetrace supports sRGB, linear, \"gamma <g>\"", e));
}

// How many channels the pyramid keeps: the colour ones (alpha dropped), fewer than three read
// as grey.
int colour_channels(const PluginParams& p, const std::string& path, int channels, const ImageFileFormat& format) {
  int colour = channels;
  if (format.alpha_channel >= 0 && format.alpha_channel < 3) colour = std::min(colour, format.alpha_channel);
  if (colour < 1) p.fail("filename", fmt::format("image \"{}\" has no colour channels", path));
  return colour >= 3 ? 3 : 1;
}

[[noreturn]] void cannot_read(const PluginParams& p, const std::string& path, const std::string& why) {
  p.fail("filename", fmt::format("cannot read image \"{}\"{}{}", path, why.empty() ? "" : ": ", why));
}

// An 8-bit PNG goes from the file to the pyramid as bytes; other images through floats.
std::unique_ptr<MipMap> make_mipmap(const PluginParams& p, const std::string& path) {
  ImageFileFormat format;
  Image image;
  if (is_png_file(path)) {
    PngSamples s;
    try {
      s = read_png_samples(path, &format);
    } catch (const std::exception& e) {
      cannot_read(p, path, e.what());
    }
    if (s.bit_depth == 8) {
      return std::make_unique<MipMap>(std::move(s.data), s.width, s.height, s.channels,
                                      colour_channels(p, path, s.channels, format), read_encoding(p, path, format),
                                      read_wrap(p));
    }
    image = to_image(s);
  } else if (std::string why; !read_image(path, &image, &format, &why)) {
    cannot_read(p, path, why);
  }
  return std::make_unique<MipMap>(image, colour_channels(p, path, image.channels, format), format.eight_bit,
                                  read_encoding(p, path, format), read_wrap(p));
}

}  // namespace

const PluginSpec& imagemap_texture_spec() {
  static const PluginSpec spec{
      "Texture", "an image file",
      "pbrt-v4's MIP map and filters (render/mipmap.h); hits carry no ray differentials, so every lookup filters "
      "level 0 (pbrt-v4 reads coarser levels where a pixel spans several texels); no `octahedralsphere` wrap; 8-bit "
      "images other than PNG default to sRGB (pbrt-v4: only `.png`).",
      std::vector<ParamSpec>{
          param::string("filename").shown_default("required").describe("PNG, EXR, or any format OpenImageIO reads"),
          param::string("filter", "bilinear").in({"point", "bilinear", "trilinear", "ewa", "EWA"}),
          param::real("maxanisotropy", 8).at_least(1), param::string("wrap", "repeat").in({"repeat", "black", "clamp"}),
          param::string("encoding")
              .shown_default("sRGB for `.png` and 8-bit images, else linear")
              .describe("`sRGB`, `linear` or `\"gamma g\"`; ignored for floating-point images"),
          param::real("scale", 1).describe("multiplies the values"),
          param::boolean("invert", false).describe("1 − value")} +
          TextureMapping2D::declared()};
  return spec;
}

namespace {

ImageLookup open_image(const TextureContext& ctx) {
  const PluginParams p(ctx.params, imagemap_texture_spec(), "imagemap");
  if (!p.has("filename")) p.fail("filename", "an imagemap texture needs a \"filename\"");
  std::string path = resolve_scene_file(ctx.search_dir, p.get_string("filename"));
  if (!std::filesystem::is_regular_file(path))
    p.fail_missing_file("filename", fmt::format("image file \"{}\" not found", path));

  ImageLookup l;
  // Textures that read one file with the same wrap and encoding share its pyramid.
  const std::string key =
      fmt::format("{}\n{}\n{}", path, p.get_string("wrap"), p.has("encoding") ? p.get_string("encoding") : "");
  l.map = &ctx.textures.mipmap(key, [&] { return make_mipmap(p, path); });
  l.filter = read_filter(p);
  l.max_anisotropy = p.get_float("maxanisotropy");
  l.scale = p.get_float("scale");
  l.invert = p.get_bool("invert");
  l.mapping = TextureMapping2D::read(ctx, p);
  return l;
}

class FloatImageTexture final : public FloatTexture {
 public:
  explicit FloatImageTexture(ImageLookup l) : l_(std::move(l)) {}
  // One channel as is; RGB averaged, as pbrt-v4 does for a float lookup of a colour image.
  float evaluate(const TextureEvalContext& ctx) const override {
    float v[3];
    int n = l_.fetch(ctx, v);
    if (n == 0) return 0.f;
    if (n < 3) return v[0];
    return (v[0] + v[1] + v[2]) / 3.f;
  }

 private:
  ImageLookup l_;
};

class SpectrumImageTexture final : public ImageTexture {
 public:
  explicit SpectrumImageTexture(ImageLookup l) : l_(std::move(l)) {}
  // Grey images give grey; two-channel (grey, alpha) images use the grey channel.
  RGB rgb(const TextureEvalContext& ctx) const override {
    float v[3];
    int n = l_.fetch(ctx, v);
    if (n == 0) return RGB(0.f);
    if (n < 3) return RGB(v[0]);
    return RGB(v[0], v[1], v[2]);
  }
  // The RGB to a spectrum at every lookup: the sigmoid table makes that a few dozen ns.
  SampledSpectrum evaluate(const TextureEvalContext& ctx, const SampledWavelengths& lambda) const override {
    return Spectrum::from_rgb(rgb(ctx), ctx.spectrum_type).sample(lambda);
  }

 private:
  ImageLookup l_;
};

}  // namespace

std::unique_ptr<FloatTexture> create_imagemap_float_texture(const TextureContext& ctx) {
  return std::make_unique<FloatImageTexture>(open_image(ctx));
}

std::unique_ptr<SpectrumTexture> create_imagemap_spectrum_texture(const TextureContext& ctx) {
  return create_imagemap_image_texture(ctx);
}

std::unique_ptr<ImageTexture> create_imagemap_image_texture(const TextureContext& ctx) {
  return std::make_unique<SpectrumImageTexture>(open_image(ctx));
}

}  // namespace eyetrace
