// A fingerprint of everything that determines a render's image: the scene description, the
// options that change the image and the bytes of every file the scene reads. A resumed render
// (render/render_state.h) must carry the fingerprint of the render that resumes it.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "scene/scene_description.h"

namespace eyetrace {

// Every directive, parameter value (exactly, as parsed) and transform of the scene, plus
// `options` (the command-line settings that change the image) and the content of every file in
// `files_read` (meshes, images, lens files: a changed texture must not resume into an old
// image), hashed. An unreadable file is an error naming it.
uint64_t scene_fingerprint(const SceneDescription& desc, const std::string& options,
                           const std::vector<std::string>& files_read);

}  // namespace eyetrace
