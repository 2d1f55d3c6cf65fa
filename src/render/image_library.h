// Everything eyetrace asks of OpenImageIO, as a small abstract interface. OpenImageIO pulls in
// about 260 shared libraries (ffmpeg, GDAL, OpenVDB...) that cost 0.16 s and 130 MB at every
// process start, so it lives in a module of its own (src/oiio, libeyetrace_oiio.so) that is
// loaded the first time an image other than OpenEXR or PNG is read, or other than OpenEXR is
// written (image_library_loader.h). OpenEXR files are read and written without it (exr_file.h),
// PNG files read without it (png_file.h).
//
// The module is self-contained: it sees only this header and image_io.h's Image, and reports
// failures as return values, never as exceptions across the boundary.
#pragma once
#include <map>
#include <string>

#include "render/image_io.h"

namespace eyetrace {

// How a file stores its pixels, for the callers that decode them.
struct ImageFileFormat {
  bool integer = false;     // integer pixels (PNG, JPEG, 8/16-bit TIFF): usually sRGB-encoded
  bool eight_bit = false;   // 8-bit integer pixels
  std::string color_space;  // the file's own statement ("" when it makes none)
  int alpha_channel = -1;   // index of the alpha channel, -1 when none is known
};

class ImageLibrary {
 public:
  // All channels as float, in the order OpenImageIO gives them; false with the reason in *error.
  virtual bool read(const std::string& path, Image* image, ImageFileFormat* format, std::string* error) = 0;
  // Writes `pixels` (image's size and channel names; values already encoded when `eight_bit`)
  // to `path`, whose extension picks the format; `metadata` as string attributes.
  virtual bool write(const std::string& path, const Image& image, const float* pixels, bool eight_bit,
                     const std::map<std::string, std::string>& metadata, std::string* error) = 0;
  // One string attribute of the file's header ("" if absent or unreadable).
  virtual std::string attribute(const std::string& path, const std::string& name) = 0;

 protected:
  ~ImageLibrary() = default;  // the module's single instance lives as long as the process
};

}  // namespace eyetrace

// The module's one exported symbol.
#define EYETRACE_IMAGE_LIBRARY_ENTRY "eyetrace_image_library"
extern "C" eyetrace::ImageLibrary* eyetrace_image_library();
