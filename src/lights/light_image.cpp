#include "lights/light_image.h"

#include <filesystem>

#include "scene/scene_files.h"

namespace eyetrace {

RGBImage read_light_image(const PluginParams& params, const std::string& search_dir, const std::string& light_name) {
  if (!params.has("filename"))
    params.fail("filename",
                fmt::format("a \"{}\" light needs \"filename\", the image of its distribution", light_name));
  const std::string path = resolve_scene_file(search_dir, params.get_string("filename"));
  if (!std::filesystem::is_regular_file(path))
    params.fail_missing_file("filename", fmt::format("image \"{}\" not found", path));
  std::string error;
  size_t non_finite = 0;
  std::optional<RGBImage> image = read_rgb_image(path, &error, &non_finite);
  if (!image) params.fail("filename", fmt::format("cannot read image \"{}\": {}", path, error));
  if (non_finite > 0)
    params.fail("filename", fmt::format("image \"{}\" has {} non-finite value(s) and so is not suitable as a light",
                                        path, non_finite));
  return std::move(*image);
}

}  // namespace eyetrace
