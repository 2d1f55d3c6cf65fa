// The image file a light reads its distribution from (goniometric, projection): the "filename"
// parameter resolved against the scene's directory and read as linear RGB (lights/rgb_image.h).
// A missing parameter, a missing or unreadable file, and an image with a non-finite value (which
// pbrt-v4 also refuses as a light) are errors naming the file and the parameter.
#pragma once
#include <string>

#include "lights/rgb_image.h"
#include "scene/param_spec.h"

namespace eyetrace {

RGBImage read_light_image(const PluginParams& params, const std::string& search_dir, const std::string& light_name);

}  // namespace eyetrace
