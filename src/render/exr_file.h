// OpenEXR files read and written through the OpenEXR library itself, so that rendering to
// .exr (the usual output) and reading .exr environment maps never loads OpenImageIO
// (render/image_library.h says why that matters).
//
// What is written is what OpenImageIO 2.4 wrote before: one part, scan lines, 32-bit float
// channels named as given, RLE compression, the data window equal to the display window, the
// metadata as string attributes and capDate (the time of writing, "YYYY:MM:DD HH:MM:SS").
// What is read comes in OpenImageIO's channel order, so readers see what they saw before.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "render/image_io.h"

namespace eyetrace {

// True when the file starts with OpenEXR's magic number.
bool is_exr_file(const std::string& path);

// Writes `pixels` (image.channels floats per pixel, row-major, top row first) to `path` as it
// stands (image_io.h makes the write atomic). Throws std::exception with the library's reason.
void write_exr(const std::string& path, const Image& image, const std::map<std::string, std::string>& metadata);

// Every channel as float (half and unsigned int channels converted) over the data window.
// Throws std::exception with the reason (image_io.h names the file).
Image read_exr(const std::string& path);

// One string attribute of the header ("" if absent or not a string); "DateTime" reads capDate.
std::string read_exr_attribute(const std::string& path, const std::string& name);

// OpenImageIO 2.4's order for EXR channel names: by layer (the part before the last '.'; no
// layer first), then within a layer the names it knows (R, G, B, Y, A, Z... or, in a layer with
// X and Y or Z, R, G, B, X, Y, Z, A...) in that order, then the rest by name. Returns indices
// into `names`.
std::vector<int> oiio_channel_order(const std::vector<std::string>& names);

}  // namespace eyetrace
