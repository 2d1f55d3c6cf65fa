#include "scene/texture_store.h"

#include "render/mipmap.h"

namespace eyetrace {

namespace {

// Lets "texture reflectance" name a float texture: grey of that value.
class FloatAsSpectrumTexture final : public SpectrumTexture {
 public:
  explicit FloatAsSpectrumTexture(const FloatTexture* f) : f_(f) {}
  SampledSpectrum evaluate(const TextureEvalContext& ctx, const SampledWavelengths&) const override {
    return SampledSpectrum(f_->evaluate(ctx));
  }

 private:
  const FloatTexture* f_;
};

template <typename Map>
std::vector<std::string> names_of(const Map& m) {
  std::vector<std::string> names;
  for (const auto& [n, t] : m) names.push_back(n);
  return names;
}

[[noreturn]] void unknown_texture(const ParameterList& params, const std::string& param, const std::string& tex,
                                  const char* kind, const std::vector<std::string>& known) {
  std::string hint = closest_match(tex, known);
  params.fail(param, fmt::format("no {} texture named \"{}\" has been defined{}", kind, tex,
                                 hint.empty() ? "" : fmt::format(" (did you mean \"{}\"?)", hint)));
}

bool is_texture_ref(const ParameterList& params, const std::string& name) {
  const Param* p = params.find(name);
  return p && p->canonical_type() == "texture";
}

}  // namespace

TextureStore::TextureStore() = default;

TextureStore::~TextureStore() {
  // Textures point into the pyramids: release them first.
  floats_.clear();
  spectra_.clear();
  float_store_.clear();
  spectrum_store_.clear();
  mipmaps_.clear();
}

void TextureStore::add_float(const std::string& name, std::unique_ptr<FloatTexture> tex, const SourceLoc& loc) {
  if (floats_.count(name)) fail(loc, "float texture \"{}\" is defined twice", name);
  floats_[name] = keep(std::move(tex));
}

void TextureStore::add_spectrum(const std::string& name, std::unique_ptr<SpectrumTexture> tex, const SourceLoc& loc) {
  if (spectra_.count(name)) fail(loc, "spectrum texture \"{}\" is defined twice", name);
  spectra_[name] = keep(std::move(tex));
}

const FloatTexture* TextureStore::named_float(const std::string& name) const {
  auto it = floats_.find(name);
  return it == floats_.end() ? nullptr : it->second;
}

const SpectrumTexture* TextureStore::named_spectrum(const std::string& name) const {
  auto it = spectra_.find(name);
  return it == spectra_.end() ? nullptr : it->second;
}

const FloatTexture* TextureStore::float_param(const ParameterList& params, const std::string& name, float def) {
  if (const FloatTexture* t = float_param_or_null(params, name)) return t;
  return keep(std::make_unique<ConstantFloatTexture>(def));
}

const FloatTexture* TextureStore::float_param_or_null(const ParameterList& params, const std::string& name) {
  if (is_texture_ref(params, name)) {
    std::string tex = params.get_texture(name);
    if (const FloatTexture* t = named_float(tex)) return t;
    if (named_spectrum(tex))
      params.fail(name,
                  fmt::format("texture \"{}\" is a spectrum texture, but \"{}\" needs a float texture", tex, name));
    unknown_texture(params, name, tex, "float", names_of(floats_));
  }
  if (!params.has(name)) return nullptr;
  return keep(std::make_unique<ConstantFloatTexture>(params.get_float(name, 0.f)));
}

// Absent: the declared default as a constant texture, or null when the table gives none.
const FloatTexture* TextureStore::float_param(const PluginParams& params, const std::string& name) {
  if (params.has(name)) return float_param_or_null(params.list(), name);
  const ParamSpec& spec = *params.spec().find(name);  // has() checked that it is declared
  return spec.has_default ? keep(std::make_unique<ConstantFloatTexture>(float(spec.default_numbers.at(0)))) : nullptr;
}

const SpectrumTexture* TextureStore::spectrum_param(const PluginParams& params, const std::string& name,
                                                    SpectrumType use) {
  if (params.has(name)) return spectrum_param_or_null(params.list(), name, use);
  const ParamSpec& spec = *params.spec().find(name);
  return spec.has_default ? keep(std::make_unique<ConstantSpectrumTexture>(RGB(float(spec.default_numbers.at(0)))))
                          : nullptr;
}

const SpectrumTexture* TextureStore::spectrum_param(const ParameterList& params, const std::string& name,
                                                    const RGB& def, SpectrumType use) {
  if (const SpectrumTexture* t = spectrum_param_or_null(params, name, use)) return t;
  return keep(std::make_unique<ConstantSpectrumTexture>(def));
}

const SpectrumTexture* TextureStore::spectrum_param_or_null(const ParameterList& params, const std::string& name,
                                                            SpectrumType use) {
  if (is_texture_ref(params, name)) {
    std::string tex = params.get_texture(name);
    if (const SpectrumTexture* t = named_spectrum(tex)) return t;
    if (const FloatTexture* f = named_float(tex)) return keep(std::make_unique<FloatAsSpectrumTexture>(f));
    unknown_texture(params, name, tex, "spectrum", names_of(spectra_));
  }
  // A texture's value is a shape, never an emission: spectra given as such are not normalised.
  // The constant texture keeps both readings of an RGB; `use` only decides the range check.
  std::optional<SpectrumValue> v = params.get_spectrum(name, use);
  if (!v) return nullptr;
  if (v->rgb) return keep(std::make_unique<ConstantSpectrumTexture>(*v->rgb));
  return keep(std::make_unique<ConstantSpectrumTexture>(v->spectrum));
}

const MipMap& TextureStore::mipmap(const std::string& key, const std::function<std::unique_ptr<MipMap>()>& make) {
  std::unique_ptr<MipMap>& m = mipmaps_[key];
  if (!m) m = make();
  return *m;
}

const FloatTexture* TextureStore::keep(std::unique_ptr<FloatTexture> tex) {
  float_store_.push_back(std::move(tex));
  return float_store_.back().get();
}

const SpectrumTexture* TextureStore::keep(std::unique_ptr<SpectrumTexture> tex) {
  spectrum_store_.push_back(std::move(tex));
  return spectrum_store_.back().get();
}

}  // namespace eyetrace
