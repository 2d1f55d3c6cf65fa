// Eye presets. Every model is a data file (eye_model.h), embedded at build time or registered
// at run time; its accommodation is the law the file names (accommodation_laws.h). What else
// varies with the options (age limit, refractive error, retina, pupil, corneal cylinder, iris
// decentration, contact and spectacle lenses, wavelength) is applied here, in that order, each
// step a small function of a Prescription in its own file. No model is named in this code.
#include "optics/eye_models.h"

#include <cmath>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>

#include <fmt/format.h>

#include "optics/accommodation_amplitude.h"
#include "optics/accommodation_laws.h"
#include "optics/contact_lens.h"
#include "optics/corneal_astigmatism.h"
#include "optics/embedded_data.h"
#include "optics/optics_error.h"
#include "optics/paraxial.h"
#include "optics/refractive_ametropia.h"

namespace eyetrace::optics {

namespace {

[[noreturn]] void bad_option(const char* option, const std::string& message) { throw OpticsError(option, message); }

std::string join(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

// Every model: the embedded data files first, then any registered at run time. std::map
// keeps references stable when models are added.
class ModelTable {
 public:
  static ModelTable& instance() {
    static ModelTable table;
    return table;
  }
  const EyeModel& add(EyeModel m) {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto key = std::make_pair(m.name, m.variant);
    const auto it = models_.find(key);
    if (it != models_.end())
      throw OpticsError(fmt::format("{}: eye model '{}'{} is already defined by {}", m.origin, m.name,
                                    m.variant.empty() ? "" : " variant '" + m.variant + "'", it->second.origin));
    return models_.emplace(key, std::move(m)).first->second;
  }
  std::vector<std::string> names() const {
    std::lock_guard<std::mutex> lock(mutex_);
    std::vector<std::string> out;
    for (const auto& [key, m] : models_)
      if (out.empty() || out.back() != key.first) out.push_back(key.first);
    return out;
  }
  // "" (the default) first, then the others in order; empty for an unknown model.
  std::vector<std::string> variants(const std::string& model) const {
    std::lock_guard<std::mutex> lock(mutex_);
    std::vector<std::string> out;
    for (auto it = models_.lower_bound({model, ""}); it != models_.end() && it->first.first == model; ++it)
      out.push_back(it->first.second);
    return out;
  }
  const EyeModel* find(const std::string& model, const std::string& variant) const {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto it = models_.find({model, variant});
    return it == models_.end() ? nullptr : &it->second;
  }

 private:
  ModelTable() {
    for (const auto& [file, text] : embedded::files()) add(eye_model_from_json_text(text, file));
  }
  mutable std::mutex mutex_;
  std::map<std::pair<std::string, std::string>, EyeModel> models_;
};

// The model and variant named by the options; errors name the option.
const EyeModel& model_of(const std::string& model, const std::string& variant) {
  const std::vector<std::string> variants = eye_model_variants(model);
  if (const EyeModel* m = ModelTable::instance().find(model, variant)) return *m;
  std::vector<std::string> shown;
  for (const std::string& v : variants) shown.push_back(v.empty() ? "\"\" (default)" : v);
  bad_option("variant", fmt::format("model '{}' has no variant '{}'; valid variants: {}", model, variant, join(shown)));
}

Prescription accommodated(const EyeModel& m, double A) {
  return find_accommodation_law(m.accommodation_law).apply(m, A);
}

// Axial: the vitreous depth; refractive: the anterior corneal radius (refractive_ametropia.h).
// Either is solved on the relaxed eye and kept when it accommodates (all models).
void build_in_refractive_error(const EyeModel& model, const EyeOptions& o, Prescription& p) {
  const Prescription relaxed = accommodated(model, 0.0);
  if (o.ametropia == Ametropia::Refractive) {
    const double r0 = 1.0 / relaxed.surfaces[0].profile.curvature;
    const double r = set_refraction_by_cornea(p, relaxed, o.refractive_error_D);
    try {
      validate(p);
    } catch (const OpticsError& e) {
      bad_option("refractiveerror", fmt::format("the anterior cornea of radius {:.4g} mm this needs: {}", r, e.what()));
    }
    p.notes.push_back(
        fmt::format("refractive error {} D (refractive): anterior corneal radius {:.4f} mm instead of "
                    "{:.4f} mm",
                    o.refractive_error_D, r, r0));
    return;
  }
  const double old_length = relaxed.axial_length_mm();
  double new_length;
  try {
    new_length = image_position_for_refraction(relaxed, o.refractive_error_D);
  } catch (const OpticsError& e) {
    bad_option("refractiveerror", e.what());
  }
  p.surfaces[p.image_index() - 1].thickness_mm += new_length - old_length;
  p.notes.push_back(fmt::format("refractive error {} D: axial length {:.4f} mm instead of {:.4f} mm",
                                o.refractive_error_D, new_length, old_length));
}

// Corneal cylinder, decentred iris, contact lens, spectacle lens: each a function of its own file.
void add_corrections(const EyeOptions& o, Prescription& p) {
  if (o.cylinder_D != 0.0 || o.axis_deg != 0.0) set_corneal_cylinder(p, o.cylinder_D, o.axis_deg);
  if (o.pupil_decentration_x_mm != 0.0 || o.pupil_decentration_y_mm != 0.0)
    set_pupil_decentration(p, o.pupil_decentration_x_mm, o.pupil_decentration_y_mm);
  if (o.contact_lens_D != 0.0) add_contact_lens(p, o.contact_lens_D);
  if (o.spectacle) add_spectacle_lens(p, *o.spectacle);
}

void check_finite(const char* option, double value) {
  if (!std::isfinite(value)) bad_option(option, fmt::format("{} is not a finite number", value));
}

}  // namespace

std::vector<std::string> eye_model_names() { return ModelTable::instance().names(); }

std::vector<std::string> eye_model_variants(const std::string& model) {
  std::vector<std::string> variants = ModelTable::instance().variants(model);
  if (variants.empty())
    bad_option("model", fmt::format("unknown eye model '{}'; valid models: {}", model, join(eye_model_names())));
  return variants;
}

double max_accommodation_D(const std::string& model, const std::string& variant) {
  return model_of(model, variant).max_accommodation_D;
}

const EyeModel& register_eye_model_text(const std::string& text, const std::string& origin) {
  return ModelTable::instance().add(eye_model_from_json_text(text, origin));
}

const EyeModel& register_eye_model_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw OpticsError(fmt::format("{}: cannot read the eye model file", path));
  std::ostringstream text;
  text << in.rdbuf();
  return register_eye_model_text(text.str(), path);
}

Prescription make_eye(const EyeOptions& o) {
  const EyeModel& model = model_of(o.model, o.variant);
  check_finite("accommodation", o.accommodation_D);
  check_finite("pupildiameter", o.pupil_diameter_mm);
  check_finite("refractiveerror", o.refractive_error_D);
  check_finite("wavelength", o.wavelength_nm);
  if (o.retina_radius_mm) check_finite("retinaradius", *o.retina_radius_mm);

  if (!(o.pupil_diameter_mm > 0.0 && o.pupil_diameter_mm <= kMaxPupilDiameter_mm))
    bad_option("pupildiameter", fmt::format("{} mm is outside (0, {}] mm", o.pupil_diameter_mm, kMaxPupilDiameter_mm));
  const double max_a = model.max_accommodation_D;
  if (o.accommodation_D < 0.0 || o.accommodation_D > max_a)
    bad_option("accommodation", max_a == 0.0 ? fmt::format("model '{}' has no accommodation model (only 0 D); got {} D",
                                                           o.model, o.accommodation_D)
                                             : fmt::format("{} D is outside the range of model '{}' [0, {:.5g}] D",
                                                           o.accommodation_D, o.model, max_a));
  if (std::abs(o.refractive_error_D) > kMaxRefractiveError_D)
    bad_option("refractiveerror", fmt::format("{} D is outside [-{}, {}] D", o.refractive_error_D,
                                              kMaxRefractiveError_D, kMaxRefractiveError_D));
  if (o.retina_radius_mm && *o.retina_radius_mm > 0.0)
    bad_option("retinaradius", fmt::format("{} mm must be negative (centre of curvature in "
                                           "front of the retina) or 0 for flat",
                                           *o.retina_radius_mm));
  if (o.wavelength_nm != 0.0 && (o.wavelength_nm < kMinWavelength_nm || o.wavelength_nm > kMaxWavelength_nm))
    bad_option("wavelength", fmt::format("{} nm is outside [{}, {}] nm (0 = the model's reference)", o.wavelength_nm,
                                         kMinWavelength_nm, kMaxWavelength_nm));

  Prescription p = accommodated(model, o.accommodation_D);
  p.variant = o.variant;
  const int retina = p.image_index();

  if (o.age_years) {
    const double amplitude_check_D = produced_accommodation_D(accommodated(model, 0.0), p);
    check_accommodation_for_age(*o.age_years, o.accommodation_D, amplitude_check_D);
  }
  if (o.refractive_error_D != 0.0) build_in_refractive_error(model, o, p);
  if (o.retina_radius_mm) p.surfaces[retina].profile = SurfaceProfile::from_radius(*o.retina_radius_mm, 0.0);
  set_stop_diameter(p, o.pupil_diameter_mm);
  add_corrections(o, p);
  if (o.wavelength_nm != 0.0 && o.wavelength_nm != p.reference_wavelength_nm) {
    p = at_wavelength(p, o.wavelength_nm);
    for (const Medium& m : p.media)
      if (m.dispersion.law == DispersionLaw::None && m.index != 1.0) {
        p.notes.push_back(
            fmt::format("medium '{}' has no dispersion data: its index is "
                        "the same at every wavelength",
                        m.name));
      }
  }
  try {
    validate(p);
  } catch (const OpticsError& e) {
    throw OpticsError(fmt::format("eye model '{}' with these options is not a valid system: {}", o.model, e.what()));
  }
  return p;
}

}  // namespace eyetrace::optics
