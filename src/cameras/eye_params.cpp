#include "cameras/eye_params.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include "optics/lens_file.h"
#include "optics/optics_error.h"
#include "optics/paraxial.h"
#include "scene/scene_files.h"

namespace eyetrace {

namespace {

// A float parameter in full double precision (the parser keeps doubles; get_float marks the
// parameter used and checks its type).
double get_double(const ParameterList& params, const std::string& name, double def) {
  params.get_float(name, static_cast<float>(def));
  const Param* p = params.find(name);
  return p && !p->numbers.empty() ? p->numbers[0] : def;
}

bool has_curved_retina(const optics::EyeOptions& o) {
  optics::EyeOptions relaxed = o;
  relaxed.accommodation_D = 0.0;
  relaxed.refractive_error_D = 0.0;
  relaxed.retina_radius_mm.reset();
  return !optics::make_eye(relaxed).surfaces.back().profile.is_flat();
}

void read_retina(const ParameterList& params, optics::EyeOptions& o) {
  const std::string shape = params.get_string("retina", "");
  if (shape != "" && shape != "curved" && shape != "flat")
    params.fail("retina", fmt::format("\"{}\" is not a retina shape; use \"curved\" or \"flat\"", shape));
  if (params.has("retinaradius")) {
    const double r = get_double(params, "retinaradius", 0.0);
    if (!std::isfinite(r) || std::abs(r) < 1.0 || std::abs(r) > 1000.0)
      params.fail("retinaradius", fmt::format("{} mm is not a retina radius; give its magnitude in [1, 1000] mm "
                                              "(the retina always curves towards the lens)",
                                              r));
    if (shape == "flat") params.fail("retinaradius", "a flat retina has no radius; drop one of the two");
    o.retina_radius_mm = -std::abs(r);  // optics convention: centre of curvature in front
    return;
  }
  if (shape == "flat") o.retina_radius_mm = 0.0;
  if (shape == "curved" && !has_curved_retina(o))
    params.fail("retina", fmt::format("eye model '{}' has a flat retina; give \"float retinaradius\" (mm) to "
                                      "curve it",
                                      o.model));
}

}  // namespace

optics::Prescription eye_prescription_from_params(const std::string& camera_name, const ParameterList& params) {
  optics::EyeOptions o;
  o.model = camera_name == "eye" ? params.get_string("model", "navarro") : camera_name;
  o.variant = params.get_string("variant", "");
  o.accommodation_D = get_double(params, "accommodation", 0.0);
  o.pupil_diameter_mm = get_double(params, "pupildiameter", kDefaultPupilDiameter_mm);
  o.refractive_error_D = get_double(params, "refractiveerror", 0.0);
  o.wavelength_nm = get_double(params, "wavelength", 0.0);
  if (params.has("wavelength") && o.wavelength_nm == 0.0)
    params.fail("wavelength", "0 nm is not a wavelength (omit it for the model's reference wavelength)");
  try {
    optics::eye_model_variants(o.model);  // unknown model first, before anything depends on it
    read_retina(params, o);
    return optics::make_eye(o);
  } catch (const optics::OpticsError& e) {
    // The eye options are named as the camera's parameters; an error naming none (an invalid
    // system) belongs to the model.
    params.fail(e.option().empty() ? "model" : e.option(), e.message());
  }
}

LensSystemCamera::Settings eye_view_settings(const std::string& camera_name, const ParameterList& params) {
  LensSystemCamera::Settings s;
  s.name = camera_name;
  s.fov_deg = get_double(params, "fov", kDefaultEyeFov_deg);
  if (!(s.fov_deg > 0.0 && s.fov_deg < 180.0))
    params.fail("fov", fmt::format("{} degrees is not in (0, 180)", s.fov_deg));
  const std::string mapping = params.get_string("mapping", "angle");
  if (!parse_field_mapping(mapping, &s.mapping))
    params.fail("mapping", fmt::format("\"{}\" is not a mapping; use \"angle\", \"flat\" or \"retina\"", mapping));
  const double metres_per_unit = get_double(params, "sceneunit", 1.0);
  if (!(metres_per_unit > 0.0 && std::isfinite(metres_per_unit)))
    params.fail("sceneunit", fmt::format("{} metres per scene unit must be positive", metres_per_unit));
  s.scene_units_per_mm = 1e-3 / metres_per_unit;
  return s;
}

optics::Prescription realistic_prescription_from_params(const ParameterList& params, const std::string& search_dir) {
  const std::string file = params.get_string("lensfile", "");
  if (file.empty()) params.fail("lensfile", "the realistic camera needs a lens file (\"string lensfile\")");
  const double aperture = get_double(params, "aperturediameter", kDefaultApertureDiameter_mm);
  if (!(aperture > 0.0 && std::isfinite(aperture)))
    params.fail("aperturediameter", fmt::format("{} mm must be positive", aperture));
  const double focus_m = get_double(params, "focusdistance", kDefaultFocusDistance);
  if (!(focus_m > 0.0 && std::isfinite(focus_m)))
    params.fail("focusdistance", fmt::format("{} must be positive", focus_m));
  std::filesystem::path path(resolve_scene_file(search_dir, file));

  optics::Prescription p;
  try {
    p = optics::read_lens_file(path.string());
  } catch (const optics::OpticsError& e) {
    params.fail("lensfile", e.what());
  }
  // pbrt-v4 clamps an aperture wider than the lens's stop, with a warning; so do we.
  if (aperture > p.stop_diameter_mm()) {
    warn(params.find("aperturediameter") ? params.find("aperturediameter")->loc : params.loc(),
         fmt::format("aperture diameter {} mm is larger than the stop of {} ({} mm); clamped", aperture, file,
                     p.stop_diameter_mm()));
  } else {
    optics::set_stop_diameter(p, aperture);
  }
  // pbrt measures the focus distance from the film; the paraxial solve needs it from the first
  // vertex, which moves with the film: a few fixed-point steps converge (the film moves by
  // millimetres while the distance is metres).
  try {
    for (int i = 0; i < 8; ++i) {
      const double from_vertex_mm = focus_m * 1000.0 - p.axial_length_mm();
      if (!(from_vertex_mm > 0.0))
        params.fail("focusdistance",
                    fmt::format("{} m lies inside the lens ({:.4g} mm long)", focus_m, p.axial_length_mm()));
      optics::set_refraction(p, -1000.0 / from_vertex_mm);
    }
    optics::validate(p);
  } catch (const optics::OpticsError& e) {
    params.fail("focusdistance", fmt::format("cannot focus at {} m: {}", focus_m, e.what()));
  }
  return p;
}

LensSystemCamera::Settings realistic_view_settings(const ParameterList& params, IVec2 resolution) {
  LensSystemCamera::Settings s;
  s.name = "realistic";
  s.mapping = FieldMapping::Flat;
  const double diagonal = get_double(params, "filmdiagonal", kDefaultFilmDiagonal_mm);
  if (!(diagonal > 0.0 && std::isfinite(diagonal)))
    params.fail("filmdiagonal", fmt::format("{} mm must be positive", diagonal));
  const double pixels = std::sqrt(double(resolution.x) * resolution.x + double(resolution.y) * resolution.y);
  s.film_half_mm = 0.5 * std::min(resolution.x, resolution.y) * diagonal / pixels;
  s.scene_units_per_mm = 1e-3;  // pbrt: scene units are metres
  return s;
}

optics::Prescription prescription_from_camera_params(const std::string& camera_name, const ParameterList& params,
                                                     const std::string& search_dir) {
  if (camera_name == "realistic") return realistic_prescription_from_params(params, search_dir);
  std::vector<std::string> lens_cameras = optics::eye_model_names();
  if (camera_name == "eye" || std::find(lens_cameras.begin(), lens_cameras.end(), camera_name) != lens_cameras.end())
    return eye_prescription_from_params(camera_name, params);
  lens_cameras.insert(lens_cameras.begin(), {"eye", "realistic"});
  std::string list;
  for (const std::string& n : lens_cameras) list += (list.empty() ? "\"" : ", \"") + n + "\"";
  const std::string hint = closest_match(camera_name, lens_cameras);
  throw_error(params.loc(), fmt::format("camera \"{}\" has no lens prescription{}; use one of {}", camera_name,
                                        hint.empty() ? "" : fmt::format(" (did you mean \"{}\"?)", hint), list));
}

}  // namespace eyetrace
