// Schematic eye presets: EyeOptions -> a validated Prescription (cornea first, or a contact or
// spectacle lens before it; iris stop at the anterior lens vertex, retina last). Each model is
// one data file (data/eyes/<model>.json, embedded at build time, or registered at run time with
// register_eye_model_file) naming its accommodation law; refractive error, pupil, retina,
// wavelength and a person's corrections are code. See docs/eye-models.md and docs/eye-camera.md.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "optics/eye_model.h"
#include "optics/prescription.h"
#include "optics/spectacle_lens.h"

namespace eyetrace::optics {

// Limits of the options every model shares (make_eye checks them; the eye cameras declare them).
inline constexpr double kMaxPupilDiameter_mm = 10.0;
inline constexpr double kMaxRefractiveError_D = 30.0;

// How refractive_error_D is built in: by the axial length (the vitreous depth) or by the
// anterior corneal radius (refractive_ametropia.h).
enum class Ametropia { Axial, Refractive };

struct EyeOptions {
  std::string model;    // one of eye_model_names()
  std::string variant;  // "" = the model's default; see eye_model_variants()
  // Accommodation in dioptres. Its meaning is the model's own: the Navarro parameter D
  // (not the produced accommodation, see docs), Arizona's A, and for gullstrand/legrand the
  // accommodation actually produced.
  double accommodation_D = 0.0;
  double pupil_diameter_mm = 4.0;  // iris (aperture stop) diameter, (0, 10]
  // 0 keeps the model's published retina. Otherwise the vitreous depth (axial length) is set
  // so the relaxed eye's refraction is this value (-2 = myope with far point 0.5 m); the
  // accommodated eye then keeps that axial length.
  double refractive_error_D = 0.0;
  Ametropia ametropia = Ametropia::Axial;  // Refractive: the cornea's radius instead, same axial length
  // Retina radius (mm, < 0: centre of curvature in front of the retina; 0 = flat);
  // nullopt = the model's default. The vertex stays where the model puts it.
  std::optional<double> retina_radius_mm;
  double wavelength_nm = 0.0;  // 0 = the model's reference wavelength
  // A person's eye (issue 16 part 2), applied in this order after the above:
  // the age limits the accommodation the eye may produce (accommodation_amplitude.h);
  std::optional<double> age_years;
  // astigmatism of the anterior cornea, refraction sign, TABO axis (corneal_astigmatism.h);
  double cylinder_D = 0.0, axis_deg = 0.0;
  // the iris moved off the axis, mm (corneal_astigmatism.h);
  double pupil_decentration_x_mm = 0.0, pupil_decentration_y_mm = 0.0;
  // a soft contact lens of this back-vertex power on the cornea, 0 = none (contact_lens.h);
  double contact_lens_D = 0.0;
  // a spectacle lens in front (spectacle_lens.h).
  std::optional<SpectacleLens> spectacle;
};

// Sorted model names (the embedded ones: arizona, escudero-sanz, gullstrand, kooijman, legrand,
// navarro; and any registered since).
std::vector<std::string> eye_model_names();
// Accepted variants of a model ("" is always accepted). Throws for an unknown model.
std::vector<std::string> eye_model_variants(const std::string& model);
// [0, max] accommodation range of a model/variant in dioptres. Throws for unknown names.
double max_accommodation_D(const std::string& model, const std::string& variant = "");

// Adds a model from a data file (or its text) for the rest of the process: it is then usable
// by name like the embedded ones. Throws OpticsError naming the file and field when the file is
// invalid or its model and variant already exist.
const EyeModel& register_eye_model_file(const std::string& path);
const EyeModel& register_eye_model_text(const std::string& text, const std::string& origin);

// Throws OpticsError naming the option ("model", "variant", "accommodation", "pupildiameter",
// "refractiveerror", "retinaradius", "wavelength", "age", "cylinder", "axis", "pupildecentration",
// "contactlens", "spectacle..." and "vertexdistance") when an option is invalid.
Prescription make_eye(const EyeOptions& options);

}  // namespace eyetrace::optics
