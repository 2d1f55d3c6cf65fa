// The OpenImageIO module (render/image_library.h): eyetrace's only use of OpenImageIO, built as
// libeyetrace_oiio.so and loaded when first needed (render/image_library_loader.h). It links
// nothing of eyetrace: it sees the interface header and reports failures as values.
#include <OpenImageIO/imageio.h>
#include <OpenImageIO/texture.h>

#include <algorithm>
#include <exception>

#include "render/image_library.h"

namespace eyetrace {
namespace {

using OIIO::TextureOpt;
using OIIO::TextureSystem;

TextureOpt texture_options(const TextureLookupOptions& o) {
  TextureOpt opt;
  opt.interpmode = TextureOpt::InterpBilinear;
  // pbrt-v4's point and bilinear filters pick one MIP level from the footprint.
  switch (o.filter) {
    case TextureLookupOptions::Filter::Point:
      opt.interpmode = TextureOpt::InterpClosest;
      opt.mipmode = TextureOpt::MipModeOneLevel;
      break;
    case TextureLookupOptions::Filter::Bilinear: opt.mipmode = TextureOpt::MipModeOneLevel; break;
    case TextureLookupOptions::Filter::Trilinear: opt.mipmode = TextureOpt::MipModeTrilinear; break;
    case TextureLookupOptions::Filter::Ewa: opt.mipmode = TextureOpt::MipModeAniso; break;
  }
  opt.anisotropic = std::max(1, o.max_anisotropy);
  TextureOpt::Wrap wrap = o.wrap == TextureLookupOptions::Wrap::Black   ? TextureOpt::WrapBlack
                          : o.wrap == TextureLookupOptions::Wrap::Clamp ? TextureOpt::WrapClamp
                                                                        : TextureOpt::WrapPeriodic;
  opt.swrap = opt.twrap = wrap;
  opt.fill = 0.f;
  return opt;
}

ImageFileFormat format_of(const OIIO::ImageSpec& spec) {
  ImageFileFormat f;
  const OIIO::TypeDesc t = spec.format;
  f.integer =
      t.basetype != OIIO::TypeDesc::FLOAT && t.basetype != OIIO::TypeDesc::HALF && t.basetype != OIIO::TypeDesc::DOUBLE;
  f.eight_bit = t.basetype == OIIO::TypeDesc::UINT8;
  f.color_space = spec.get_string_attribute("oiio:ColorSpace");
  f.alpha_channel = spec.alpha_channel;
  return f;
}

class OiioTextureLookup final : public TextureLookup {
 public:
  OiioTextureLookup(TextureSystem* ts, TextureSystem::TextureHandle* handle, TextureOpt opt)
      : ts_(ts), handle_(handle), opt_(opt) {}
  bool lookup(float s, float t, float width, int n, float* out) const override {
    TextureOpt o = opt_;  // OpenImageIO may write into the options
    return ts_->texture(handle_, nullptr, o, s, t, width, 0.f, 0.f, width, n, out);
  }

 private:
  TextureSystem* ts_;
  TextureSystem::TextureHandle* handle_;
  TextureOpt opt_;
};

class OiioTextureFiles final : public TextureFiles {
 public:
  OiioTextureFiles() : ts_(TextureSystem::create(true)) {
    ts_->attribute("automip", 1);  // trilinear/ewa on plain (un-MIPmapped) images
    ts_->attribute("autotile", 64);
    ts_->attribute("max_memory_MB", 1024.f);
  }
  ~OiioTextureFiles() override {
    // The system is OpenImageIO's shared one (destroying a private one trips a sized-delete
    // mismatch inside OpenImageIO 2.4 under AddressSanitizer). Files changed on disk since
    // they were read are dropped from its cache, so a later scene sees the new contents.
    ts_->invalidate_all(false);
    TextureSystem::destroy(ts_);
  }
  std::unique_ptr<TextureLookup> open(const std::string& path, const TextureLookupOptions& options, int* channels,
                                      ImageFileFormat* format, std::string* error) override {
    OIIO::ustring upath(path);
    OIIO::ImageSpec spec;
    if (!ts_->get_imagespec(upath, 0, spec)) {
      *error = ts_->geterror();
      return nullptr;
    }
    TextureSystem::TextureHandle* handle = ts_->get_texture_handle(upath);
    if (!handle) {
      *error = ts_->geterror();
      return nullptr;
    }
    *channels = spec.nchannels;
    *format = format_of(spec);
    return std::make_unique<OiioTextureLookup>(ts_, handle, texture_options(options));
  }

 private:
  TextureSystem* ts_;
};

class OiioImageLibrary final : public ImageLibrary {
 public:
  bool read(const std::string& path, Image* image, ImageFileFormat* format, std::string* error) override {
    try {
      auto in = OIIO::ImageInput::open(path);
      if (!in) {
        *error = OIIO::geterror();
        if (error->empty()) *error = "cannot open the file";
        return false;
      }
      const OIIO::ImageSpec& spec = in->spec();
      if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0) {
        *error = "the image is empty";
        return false;
      }
      image->width = spec.width;
      image->height = spec.height;
      image->channels = spec.nchannels;
      image->channel_names = spec.channelnames;
      image->pixels.resize(size_t(spec.width) * spec.height * spec.nchannels);
      if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, image->pixels.data())) {
        *error = in->geterror();
        return false;
      }
      *format = format_of(spec);
      in->close();
      return true;
    } catch (const std::exception& e) {
      *error = e.what();
      return false;
    }
  }

  bool write(const std::string& path, const Image& image, const float* pixels, bool eight_bit,
             const std::map<std::string, std::string>& metadata, std::string* error) override {
    try {
      OIIO::ImageSpec spec(image.width, image.height, image.channels,
                           eight_bit ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT);
      if (!image.channel_names.empty()) spec.channelnames = image.channel_names;
      for (const auto& [k, v] : metadata) spec.attribute(k, v);
      if (eight_bit) spec.attribute("oiio:ColorSpace", "sRGB");
      auto out = OIIO::ImageOutput::create(path);
      if (!out) {
        *error = "cannot create a writer: " + OIIO::geterror();
        return false;
      }
      if (!(out->open(path, spec) && out->write_image(OIIO::TypeDesc::FLOAT, pixels) && out->close())) {
        *error = out->geterror();
        return false;
      }
      return true;
    } catch (const std::exception& e) {
      *error = e.what();
      return false;
    }
  }

  std::string attribute(const std::string& path, const std::string& name) override {
    auto in = OIIO::ImageInput::open(path);
    if (!in) return "";
    std::string v = in->spec().get_string_attribute(name);
    in->close();
    return v;
  }

  std::unique_ptr<TextureFiles> texture_files() override { return std::make_unique<OiioTextureFiles>(); }
};

}  // namespace
}  // namespace eyetrace

extern "C" __attribute__((visibility("default"))) eyetrace::ImageLibrary* eyetrace_image_library() {
  static eyetrace::OiioImageLibrary library;
  return &library;
}
