// The OpenImageIO module (render/image_library.h): eyetrace's only use of OpenImageIO, built as
// libeyetrace_oiio.so and loaded when first needed (render/image_library_loader.h). It links
// nothing of eyetrace: it sees the interface header and reports failures as values.
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <exception>

#include "render/image_library.h"

namespace eyetrace {
namespace {

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
};

}  // namespace
}  // namespace eyetrace

extern "C" __attribute__((visibility("default"))) eyetrace::ImageLibrary* eyetrace_image_library() {
  static eyetrace::OiioImageLibrary library;
  return &library;
}
