// pbrt-v4's "imagemap" texture, looked up through the scene's texture cache (OpenImageIO's
// TextureSystem, render/image_library.h): "filename" (relative to the scene's directory), "filter" (point, bilinear
// (default), trilinear, ewa), "wrap" (repeat (default), black, clamp), "maxanisotropy" (8), "scale" (1), "invert"
// (false: v becomes max(0, 1 - scale v) when true), "encoding" ("sRGB" by default for PNG and 8-bit files, else
// "linear"; "gamma g" also accepted), and the 2D mapping parameters. The image is opened when the texture is created,
// so a missing or unreadable file is an error that names "filename" and the path.
//
// Row 0 of an image is its top: t = 1 - v, as in pbrt-v4. The encoding is undone after
// filtering, which is exact at texel centres and a close approximation between them.
#pragma once
#include <memory>

#include "core/texture.h"
#include "scene/registry.h"

namespace eyetrace {

const PluginSpec& imagemap_texture_spec();
std::unique_ptr<FloatTexture> create_imagemap_float_texture(const TextureContext& ctx);
std::unique_ptr<SpectrumTexture> create_imagemap_spectrum_texture(const TextureContext& ctx);

// The spectrum texture, which also answers with the image's RGB itself (what a normal map
// reads: a direction, not a colour). Its spectrum is that RGB as the context's SpectrumType.
class ImageTexture : public SpectrumTexture {
 public:
  virtual RGB rgb(const TextureEvalContext& ctx) const = 0;
};
std::unique_ptr<ImageTexture> create_imagemap_image_texture(const TextureContext& ctx);

}  // namespace eyetrace
