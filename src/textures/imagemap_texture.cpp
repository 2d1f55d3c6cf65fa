#include "textures/imagemap_texture.h"

#include <cmath>
#include <filesystem>

#include "render/image_io.h"
#include "render/image_library.h"
#include "scene/scene_files.h"
#include "scene/texture_store.h"
#include "textures/texture_mapping.h"

namespace eyetrace {

namespace {

enum class Encoding { Linear, SRGB, Gamma };

// Everything an image lookup needs, shared by the float and spectrum variants.
struct ImageLookup {
  std::unique_ptr<TextureLookup> image;  // one virtual call per lookup
  int channels = 0;                      // colour channels in the file (alpha excluded when we can tell)
  Encoding encoding = Encoding::Linear;
  float gamma = 1.f;
  float scale = 1.f;
  bool invert = false;
  TextureMapping2D mapping;

  // Up to 3 channels at the hit, decoded, scaled and inverted; returns how many are valid.
  int fetch(const TextureEvalContext& ctx, float out[3]) const {
    TextureCoords c = mapping.map(ctx);
    int n = std::min(channels, 3);
    out[0] = out[1] = out[2] = 0.f;
    if (!image->lookup(c.st.x, 1.f - c.st.y, c.width, n, out)) return 0;
    for (int i = 0; i < n; ++i) out[i] = finish(out[i]);
    return n;
  }

  float finish(float v) const {
    if (encoding == Encoding::SRGB)
      v = srgb_to_linear(v);
    else if (encoding == Encoding::Gamma)
      v = std::pow(std::max(v, 0.f), gamma);
    v *= scale;
    if (invert) v = std::max(0.f, 1.f - v);
    return std::isfinite(v) ? v : 0.f;
  }
};

TextureLookupOptions read_options(const PluginParams& p) {
  TextureLookupOptions o;
  const std::string filter = p.get_string("filter");  // one of the declared choices
  o.filter = filter == "point"       ? TextureLookupOptions::Filter::Point
             : filter == "bilinear"  ? TextureLookupOptions::Filter::Bilinear
             : filter == "trilinear" ? TextureLookupOptions::Filter::Trilinear
                                     : TextureLookupOptions::Filter::Ewa;  // ewa, EWA
  o.max_anisotropy = std::max(1, int(p.get_float("maxanisotropy")));
  const std::string wrap = p.get_string("wrap");
  o.wrap = wrap == "black"   ? TextureLookupOptions::Wrap::Black
           : wrap == "clamp" ? TextureLookupOptions::Wrap::Clamp
                             : TextureLookupOptions::Wrap::Repeat;
  return o;
}

void read_encoding(const PluginParams& p, const std::string& path, const ImageFileFormat& format, ImageLookup* l) {
  bool eight_bit = format.eight_bit;
  std::string ext = std::filesystem::path(path).extension().string();
  for (auto& ch : ext) ch = char(std::tolower(static_cast<unsigned char>(ch)));
  std::string e = p.has("encoding") ? p.get_string("encoding") : ext == ".png" || eight_bit ? "sRGB" : "linear";
  if (e == "sRGB" || e == "srgb") {
    l->encoding = Encoding::SRGB;
  } else if (e == "linear") {
    l->encoding = Encoding::Linear;
  } else if (e.rfind("gamma ", 0) == 0) {
    char* end = nullptr;
    float g = std::strtof(e.c_str() + 6, &end);
    if (!(g > 0.f) || !std::isfinite(g) || (end && *end != '\0'))
      p.fail("encoding", fmt::format("bad gamma in \"{}\"", e));
    l->encoding = Encoding::Gamma;
    l->gamma = g;
  } else {
    p.fail("encoding", fmt::format("unknown encoding \"{}\"; eyetrace supports sRGB, linear, \"gamma <g>\"", e));
  }
  // Floating-point pixels are linear already (pbrt-v4 ignores the encoding for them).
  if (!format.integer) l->encoding = Encoding::Linear;
}

}  // namespace

const PluginSpec& imagemap_texture_spec() {
  static const PluginSpec spec{
      "Texture", "an image file",
      "Filtering through OpenImageIO's texture system; no `octahedralsphere` wrap; 8-bit images other than PNG "
      "default to sRGB (pbrt-v4: only `.png`).",
      std::vector<ParamSpec>{
          param::string("filename").shown_default("required").describe("any format OpenImageIO reads"),
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
  std::string name = p.get_string("filename");
  std::string path = resolve_scene_file(ctx.search_dir, name);

  ImageLookup l;
  if (!std::filesystem::is_regular_file(path))
    p.fail_missing_file("filename", fmt::format("image file \"{}\" not found", path));
  TextureFiles& files = ctx.textures.texture_files(path);
  ImageFileFormat format;
  std::string why;
  l.image = files.open(path, read_options(p), &l.channels, &format, &why);
  if (!l.image) p.fail("filename", fmt::format("cannot read image \"{}\"{}{}", path, why.empty() ? "" : ": ", why));
  if (format.alpha_channel >= 0 && format.alpha_channel < 3) l.channels = std::min(l.channels, format.alpha_channel);
  if (l.channels < 1) p.fail("filename", fmt::format("image \"{}\" has no colour channels", path));

  l.scale = p.get_float("scale");
  l.invert = p.get_bool("invert");
  read_encoding(p, path, format, &l);
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
