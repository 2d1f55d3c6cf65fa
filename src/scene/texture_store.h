// Named textures of a scene, and the lookup that lets a material parameter be either a
// constant ("rgb reflectance" [.5 .5 .5]) or a texture ("texture reflectance" "wood").
// Constants become ConstantTextures owned by the store, and so do image pyramids
// (render/mipmap.h): the image textures that read one file the same way share one.
#pragma once
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/texture.h"
#include "scene/param_spec.h"
#include "scene/params.h"

namespace eyetrace {

class MipMap;  // render/mipmap.h

class TextureStore {
 public:
  TextureStore();
  ~TextureStore();
  TextureStore(const TextureStore&) = delete;

  void add_float(const std::string& name, std::unique_ptr<FloatTexture> tex, const SourceLoc& loc);
  void add_spectrum(const std::string& name, std::unique_ptr<SpectrumTexture> tex, const SourceLoc& loc);
  const FloatTexture* named_float(const std::string& name) const;  // null if unknown
  const SpectrumTexture* named_spectrum(const std::string& name) const;

  // A "float NAME" constant or "texture NAME" reference; `def` when absent.
  const FloatTexture* float_param(const ParameterList& params, const std::string& name, float def);
  // Like float_param but null when absent.
  const FloatTexture* float_param_or_null(const ParameterList& params, const std::string& name);
  // An "rgb"/"spectrum"/"blackbody" constant or "texture NAME" reference; `def` when absent.
  // `use` is what the caller reads it as: an RGB constant read as a reflectance (Albedo) and
  // outside [0, 1] is clamped with a warning naming the parameter (scene/spectrum_param.h);
  // indices of refraction say Unbounded. Texture plugins' constants are checked as
  // reflectances, their usual use.
  const SpectrumTexture* spectrum_param(const ParameterList& params, const std::string& name, const RGB& def,
                                        SpectrumType use = SpectrumType::Albedo);
  const SpectrumTexture* spectrum_param_or_null(const ParameterList& params, const std::string& name,
                                                SpectrumType use = SpectrumType::Albedo);

  // The same for a declared parameter: its default is the table's (null when it has none).
  const FloatTexture* float_param(const PluginParams& params, const std::string& name);
  const SpectrumTexture* spectrum_param(const PluginParams& params, const std::string& name,
                                        SpectrumType use = SpectrumType::Albedo);

  // The pyramid stored under `key` (a file and how its values are decoded and wrapped), made
  // by `make` on the first call with that key.
  const MipMap& mipmap(const std::string& key, const std::function<std::unique_ptr<MipMap>()>& make);
  // Keeps `tex` alive as long as the store (for textures made on the fly).
  const FloatTexture* keep(std::unique_ptr<FloatTexture> tex);
  const SpectrumTexture* keep(std::unique_ptr<SpectrumTexture> tex);

 private:
  std::map<std::string, const FloatTexture*> floats_;
  std::map<std::string, const SpectrumTexture*> spectra_;
  std::vector<std::unique_ptr<FloatTexture>> float_store_;
  std::vector<std::unique_ptr<SpectrumTexture>> spectrum_store_;
  std::map<std::string, std::unique_ptr<MipMap>> mipmaps_;
};

}  // namespace eyetrace
