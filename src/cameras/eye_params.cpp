#include "cameras/eye_params.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>

#include <fmt/format.h>

#include "optics/accommodation_amplitude.h"
#include "optics/contact_lens.h"
#include "optics/corneal_astigmatism.h"
#include "optics/lens_file.h"
#include "optics/optics_error.h"
#include "optics/paraxial.h"
#include "optics/phase_plate.h"
#include "optics/zernike_file.h"
#include "scene/scene_files.h"

namespace eyetrace {

namespace {

std::string model_list() {
  std::string list;
  for (const std::string& m : optics::eye_model_names()) list += (list.empty() ? "`" : "`, `") + m;
  return list + "`";
}

// A person's eye (issue 16 part 2): ametropia kind, corneal astigmatism, decentred pupil, age,
// spectacle and contact lenses. The optics of each is in src/optics (named in the docs).
std::vector<ParamSpec> person_params() {
  return {
      param::string("ametropia", "axial")
          .in({"axial", "refractive"})
          .describe("How `refractiveerror` is built in: `\"axial\"` by the axial length (vitreous depth), "
                    "`\"refractive\"` by the anterior corneal radius, solved so that the eye's paraxial refraction "
                    "at the corneal vertex is `refractiveerror` (conic, lens and length stay the model's)."),
      param::real("cylinder", 0)
          .range(-20, 20)
          .with_unit("D")
          .describe("Astigmatism of the anterior cornea, as the eye's refraction cylinder at the corneal vertex "
                    "(negative: minus cylinder, the meridian `axis` + 90 is the stronger). The meridian `axis` keeps "
                    "the model's curvature."),
      param::real("axis", 0).range(0, 180).with_unit("deg").describe(
          "Axis of `cylinder`, TABO notation (0 at the examiner's right, counter-clockwise as the "
          "examiner faces the eye)."),
      param::reals("pupildecentration")
          .size(2)
          .range(-optics::kMaxPupilDecentration_mm, optics::kMaxPupilDecentration_mm)
          .shown_default("0 0")
          .with_unit("mm")
          .describe("[x y]: the iris moved off the axis, in the prescription frame of eye-models.md (+x is the "
                    "camera's −x, +y its +y; the optics report's pupil `centre_mm`)."),
      param::real("age")
          .range(0, optics::kMaxAge_years)
          .shown_default("none")
          .with_unit("years")
          .describe("Refuses accommodation the eye cannot produce at this age: more than Hofstetter's (1950) "
                    "maximum amplitude 25 − 0.4 × age D (never below 0). The accommodation compared is the change of "
                    "refraction it produces (Navarro's parameter D is not it). No age: no limit."),
      param::real("spectaclesphere")
          .range(-optics::kMaxSpectaclePower_D, optics::kMaxSpectaclePower_D)
          .shown_default("no lens")
          .with_unit("D")
          .describe("A spectacle lens of this back-vertex power in front of the eye (it or `spectaclecylinder` "
                    "puts one there): a real two-surface lens, its back radius solved from the thick-lens formula. "
                    "The eye camera's origin is then the lens's front vertex."),
      param::real("spectaclecylinder", 0)
          .range(-10, 10)
          .with_unit("D")
          .describe("The spectacle's cylinder (either sign), on a toric (biconic) back surface."),
      param::real("spectacleaxis", 0).range(0, 180).with_unit("deg").describe("Axis of `spectaclecylinder`, TABO."),
      param::real("vertexdistance", optics::kDefaultVertexDistance_mm)
          .left_open_range(0, 50)
          .with_unit("mm")
          .describe("From the spectacle's back vertex to the corneal vertex (the eye's first vertex), on the axis."),
      param::real("spectacleindex", optics::kDefaultSpectacleIndex)
          .range(1.3, 2.0)
          .describe("The spectacle's refractive index (1.5: CR-39, n_d 1.498); no dispersion."),
      param::real("spectaclethickness")
          .left_open_range(0, 30)
          .shown_default("2, or a 1 mm edge")
          .with_unit("mm")
          .describe("The spectacle's centre thickness. Default 2 mm, thicker for a plus lens so that its edge is "
                    "1 mm at its 50 mm diameter; a lens whose surfaces meet inside the diameter is an error."),
      param::real("spectaclebasecurve")
          .range(-optics::kMaxSpectaclePower_D, optics::kMaxSpectaclePower_D)
          .shown_default("Vogel's rule")
          .with_unit("D")
          .describe("Front-surface power (n − 1)/R1. Default Vogel's rule on the spherical equivalent SE: SE + 6 "
                    "(plus), SE/2 + 6 (minus), at least +0.5."),
      param::real("contactlens", 0)
          .range(-optics::kMaxContactLensPower_D, optics::kMaxContactLensPower_D)
          .with_unit("D")
          .describe("A soft contact lens of this back-vertex power (in air): a layer of index 1.43, 0.1 mm thick "
                    "(more for plus, for a 0.05 mm edge), whose back is the cornea and whose front radius gives the "
                    "power."),
  };
}

// The eye cameras' table; `eye` also takes the model's name. Ranges that depend on the model
// (accommodation, variant, retina) are checked by the optics library, which names the
// parameter too.
PluginSpec make_eye_spec(bool with_model) {
  std::vector<ParamSpec> params;
  if (with_model)
    params.push_back(
        param::string("model", "navarro").describe("`eye` only: " + model_list() + ". The named cameras fix it."));
  params =
      params +
      std::vector<ParamSpec>{
          param::string("variant", "")
              .describe("`\"wu2011\"` (navarro only): the paper's Table 1 and Eq. 1 as printed (cornea index 1.367, "
                        "retina at "
                        "24.4 mm, lens-index law with ln(D+1)); see eye-models.md §5a."),
          param::real("accommodation", 0)
              .with_unit("D")
              .describe(
                  "In the model's own sense (Navarro's parameter D, 0–15 with 10–15 extrapolated; Le Grand 0–7.05 "
                  "and Gullstrand 0–10.87 as produced accommodation; Arizona's A, 0–8; Kooijman none). `eyetrace "
                  "optics` prints the refraction it produces."),
          param::real("pupildiameter", kDefaultPupilDiameter_mm)
              .left_open_range(0, optics::kMaxPupilDiameter_mm)
              .with_unit("mm")
              .describe("Iris (aperture stop) diameter. The paper's figures use 5."),
          param::real("refractiveerror", 0)
              .range(-optics::kMaxRefractiveError_D, optics::kMaxRefractiveError_D)
              .with_unit("D")
              .describe(
                  "The relaxed eye's refraction at the corneal vertex: −2 is a myope whose far point is 0.5 m. Built "
                  "in by the axial length, or by the cornea's radius with `ametropia` `\"refractive\"`."),
          param::real("fov", kDefaultEyeFov_deg)
              .open_range(0, 180)
              .with_unit("deg")
              .describe("The full field across the **shorter** image axis."),
          param::string("mapping", "angle")
              .in({"angle", "flat", "retina"})
              .describe("How pixels map to the retina, below."),
          param::string("retina")
              .in({"curved", "flat"})
              .shown_default("model's")
              .describe("Default: curved where the model has a retinal radius (Navarro/Escudero-Sanz −12 mm, Le Grand "
                        "and Arizona −13.4, Kooijman −10.8), flat otherwise (Gullstrand, navarro `wu2011`). "
                        "`\"curved\"` on a flat-retina model needs `retinaradius`."),
          param::real("retinaradius")
              .shown_default("model's")
              .with_unit("mm")
              .describe("The retina's radius of curvature, magnitude in [1, 1000] (a retina always curves towards the "
                        "lens). Implies a curved retina."),
          param::real("wavelength")
              .range(optics::kMinWavelength_nm, optics::kMaxWavelength_nm)
              .shown_default("dispersive")
              .with_unit("nm")
              .describe("A monochromatic eye: every ray is traced at this wavelength. Absent, the eye disperses: each "
                        "sample's wavelengths are traced through each medium's dispersion law (`eyetrace optics` "
                        "lists them; Gullstrand's and Kooijman's are assumed), sharing the hero wavelength's scene "
                        "path by spectral MIS or each on a path of its own (`dispersionsampling`; "
                        "docs/spectral.md)."),
          param::boolean("diffraction", false)
              .describe("Diffraction in the image: each ray's outgoing direction is drawn from the eye's wave "
                        "point-spread function (the optics' FFT PSF, precomputed every 2.5° of field and, for a "
                        "dispersive eye, every 0.25 D of chromatic defocus from 400 nm) instead of the traced "
                        "direction, so that a point source images as the optics' PSF (docs/wavefront.md, "
                        "\"Diffraction in renders\"). A dispersive eye then keeps each sample's hero wavelength only "
                        "(no spectral MIS). Eye cameras only."),
          param::string("dispersionsampling", "auto")
              .in({"auto", "mis", "paths"})
              .describe("How a dispersive eye's four wavelengths of a sample share work: `mis`, the hero "
                        "wavelength's camera ray and scene path carry all four, weighted by spectral MIS, each "
                        "wavelength counted where it lands on the retina (with a box pixel filter each pixel then "
                        "divides by its wavelengths' shares: normalised splats); `paths`, each wavelength gets a "
                        "camera ray and scene path of its own from the same retina and pupil point (four paths a "
                        "sample); `auto`, `mis`, except `paths` with a box filter under adaptive sampling (which "
                        "cannot splat), the faster at equal error (docs/spectral.md, \"Wavelength paths\"). "
                        "Integrators that splat light paths (`bdpt`) always use `mis`. No effect on a "
                        "monochromatic eye."),
          param::string("pupilmapping", "concentric")
              .in({"concentric", "polar"})
              .describe("How the pupil sample's unit square reaches the pupil region: `concentric` (Shirley and "
                        "Chiu's concentric map to a disc, then the region's angle and radius) keeps the sampler's "
                        "strata compact; `polar` (angle and squared radius straight from the square) is the mapping "
                        "before 2026-11-26 and converges more slowly (docs/convergence.md, \"Where the eye loses "
                        "the rate\")."),
          param::string("zernikefile", "")
              .describe("A measured wavefront, relative to the scene file: OSA/ANSI Zernike coefficients (µm) over the "
                        "entrance-pupil diameter they were measured at, applied as a phase plate on the iris "
                        "(eye-camera.md, \"Zernike wavefront files\"). Rays beyond the measured pupil are blocked. "
                        "The eye is then not rotationally symmetric (eye-camera.md, \"Eyes that are not rotationally "
                        "symmetric\")."),
          param::real("sceneunit", 1)
              .above(0)
              .with_unit("m")
              .describe("Metres per scene unit (1: the scene is in metres; 0.001: in mm)."),
      };
  params = params + person_params();
  return PluginSpec{"Camera", "a ray-traced schematic eye: the image on its retina",
                    "eyetrace's own: a ray-traced schematic eye. No shutter or screen-window parameters (they are "
                    "unused-parameter errors).",
                    std::move(params), "[eye-camera.md](eye-camera.md#parameters-of-the-eye-cameras)"};
}

bool has_curved_retina(const optics::EyeOptions& o) {
  optics::EyeOptions relaxed = o;
  relaxed.accommodation_D = 0.0;
  relaxed.refractive_error_D = 0.0;
  relaxed.retina_radius_mm.reset();
  return !optics::make_eye(relaxed).surfaces.back().profile.is_flat();
}

void read_retina(const PluginParams& params, optics::EyeOptions& o) {
  const std::string shape = params.has("retina") ? params.get_string("retina") : "";
  if (params.has("retinaradius")) {
    const double r = params.get_double("retinaradius");
    if (std::abs(r) < 1.0 || std::abs(r) > 1000.0)
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

// The spectacle lens's parameters; none unless spectaclesphere or spectaclecylinder is given.
std::optional<optics::SpectacleLens> read_spectacle(const PluginParams& params) {
  if (!params.has("spectaclesphere") && !params.has("spectaclecylinder")) {
    for (const char* name :
         {"spectacleaxis", "vertexdistance", "spectacleindex", "spectaclethickness", "spectaclebasecurve"})
      if (params.has(name))
        params.fail(name, "there is no spectacle lens: give \"float spectaclesphere\" (and/or spectaclecylinder)");
    return std::nullopt;
  }
  optics::SpectacleLens l;
  l.sphere_D = params.has("spectaclesphere") ? params.get_double("spectaclesphere") : 0.0;
  l.cylinder_D = params.get_double("spectaclecylinder");
  l.axis_deg = params.get_double("spectacleaxis");
  l.vertex_distance_mm = params.get_double("vertexdistance");
  l.index = params.get_double("spectacleindex");
  if (params.has("spectaclethickness")) l.centre_thickness_mm = params.get_double("spectaclethickness");
  if (params.has("spectaclebasecurve")) l.base_curve_D = params.get_double("spectaclebasecurve");
  return l;
}

void read_person(const PluginParams& params, optics::EyeOptions& o) {
  o.ametropia =
      params.get_string("ametropia") == "refractive" ? optics::Ametropia::Refractive : optics::Ametropia::Axial;
  o.cylinder_D = params.get_double("cylinder");
  o.axis_deg = params.get_double("axis");
  if (params.has("pupildecentration")) {
    const std::vector<float> d = params.get_floats("pupildecentration");  // the table admits exactly two
    o.pupil_decentration_x_mm = d[0], o.pupil_decentration_y_mm = d[1];
  }
  if (params.has("age")) o.age_years = params.get_double("age");
  o.spectacle = read_spectacle(params);
  o.contact_lens_D = params.get_double("contactlens");
}

// "zernikefile": the measured wavefront as a phase plate on the iris (optics/phase_plate.h).
void add_zernike_plate(const PluginParams& params, const std::string& search_dir, optics::Prescription& eye) {
  const std::string file = params.get_string("zernikefile");
  if (file.empty()) return;
  const std::string path = resolve_scene_file(search_dir, file);
  if (!std::filesystem::exists(path))
    params.fail_missing_file("zernikefile", fmt::format("cannot open \"{}\": no such file", path));
  try {
    optics::add_phase_plate(eye, optics::read_zernike_file(path));
  } catch (const optics::OpticsError& e) {
    params.fail("zernikefile", e.what());
  }
}

const PluginSpec& realistic_spec() {
  static const PluginSpec spec{
      "Camera",
      "a lens system read from a lens file, as pbrt-v4's realistic camera",
      "The film diagonal is a camera parameter here (pbrt-v4: `Film \"diagonal\"`); pbrt-v4's `string aperture` "
      "(a built-in diaphragm shape or an image) is not read, so it is an unused-parameter error; weights are "
      "normalised relative illumination; an optional 5th lens-file column gives a conic constant.",
      {
          param::string("lensfile").shown_default("required").describe("the lens file, relative to the scene"),
          param::real("aperturediameter", kDefaultApertureDiameter_mm)
              .above(0)
              .with_unit("mm")
              .describe("clamped, with a warning, to the lens's stop"),
          param::real("focusdistance", kDefaultFocusDistance)
              .above(0)
              .with_unit("m")
              .describe("distance in focus, measured from the film as pbrt does"),
          param::real("filmdiagonal", kDefaultFilmDiagonal_mm).above(0).with_unit("mm"),
          shutter_open_param(),
          shutter_close_param(),
      }};
  return spec;
}

}  // namespace

const PluginSpec& eye_camera_spec(const std::string& camera_name) {
  static const PluginSpec eye = make_eye_spec(true);
  static const PluginSpec named = make_eye_spec(false);
  return camera_name == "eye" ? eye : named;
}

const PluginSpec& realistic_camera_spec() { return realistic_spec(); }

optics::Prescription eye_prescription_from_params(const std::string& camera_name, const ParameterList& list,
                                                  const std::string& search_dir) {
  const PluginParams params(list, eye_camera_spec(camera_name), camera_name);
  optics::EyeOptions o;
  o.model = camera_name == "eye" ? params.get_string("model") : camera_name;
  o.variant = params.get_string("variant");
  o.accommodation_D = params.get_double("accommodation");
  o.pupil_diameter_mm = params.get_double("pupildiameter");
  o.refractive_error_D = params.get_double("refractiveerror");
  o.wavelength_nm = params.has("wavelength") ? params.get_double("wavelength") : 0.0;
  try {
    optics::eye_model_variants(o.model);  // unknown model first, before anything depends on it
    read_retina(params, o);
    read_person(params, o);
    optics::Prescription eye = optics::make_eye(o);
    add_zernike_plate(params, search_dir, eye);
    return eye;
  } catch (const optics::OpticsError& e) {
    // The eye options are named as the camera's parameters; an error naming none (an invalid
    // system) belongs to the model.
    params.fail(e.option().empty() ? "model" : e.option(), e.message());
  }
}

LensSystemCamera::Settings eye_view_settings(const std::string& camera_name, const ParameterList& list) {
  const PluginParams params(list, eye_camera_spec(camera_name), camera_name);
  LensSystemCamera::Settings s;
  s.name = camera_name;
  s.fov_deg = params.get_double("fov");
  parse_field_mapping(params.get_string("mapping"), &s.mapping);  // the table admits only known names
  s.scene_units_per_mm = 1e-3 / params.get_double("sceneunit");
  s.dispersive = !params.has("wavelength");
  s.diffraction = params.get_bool("diffraction");
  const std::string paths = params.get_string("dispersionsampling");  // the table admits only these
  using Paths = LensSystemCamera::Settings::WavelengthPaths;
  s.wavelength_paths = paths == "mis" ? Paths::Shared : paths == "paths" ? Paths::Apart : Paths::Auto;
  s.pupil.mapping =
      params.get_string("pupilmapping") == "polar" ? PupilSampler::Mapping::Polar : PupilSampler::Mapping::Concentric;
  return s;
}

optics::Prescription realistic_prescription_from_params(const ParameterList& list, const std::string& search_dir) {
  const PluginParams params(list, realistic_spec(), "realistic");
  if (!params.has("lensfile")) params.fail("lensfile", "the realistic camera needs a lens file (\"string lensfile\")");
  const std::string file = params.get_string("lensfile");
  const double aperture = params.get_double("aperturediameter");
  const double focus_m = params.get_double("focusdistance");
  std::filesystem::path path(resolve_scene_file(search_dir, file));
  if (!std::filesystem::exists(path))
    params.fail_missing_file("lensfile", fmt::format("cannot open \"{}\": no such file", path.string()));

  optics::Prescription p;
  try {
    p = optics::read_lens_file(path.string());
  } catch (const optics::OpticsError& e) {
    params.fail("lensfile", e.what());
  }
  // pbrt-v4 clamps an aperture wider than the lens's stop, with a warning; so do we.
  if (aperture > p.stop_diameter_mm()) {
    params.warn_param("aperturediameter", fmt::format("aperture diameter {} mm is larger than the stop of {} ({} mm); "
                                                      "clamped",
                                                      aperture, file, p.stop_diameter_mm()));
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

LensSystemCamera::Settings realistic_view_settings(const ParameterList& list, IVec2 resolution) {
  const PluginParams params(list, realistic_spec(), "realistic");
  LensSystemCamera::Settings s;
  s.name = "realistic";
  s.mapping = FieldMapping::Flat;
  const double diagonal = params.get_double("filmdiagonal");
  const double pixels = std::sqrt(double(resolution.x) * resolution.x + double(resolution.y) * resolution.y);
  s.film_half_mm = 0.5 * std::min(resolution.x, resolution.y) * diagonal / pixels;
  s.scene_units_per_mm = 1e-3;  // pbrt: scene units are metres
  s.shutter = read_shutter(params);
  return s;
}

optics::Prescription prescription_from_camera_params(const std::string& camera_name, const ParameterList& params,
                                                     const std::string& search_dir) {
  if (camera_name == "realistic") return realistic_prescription_from_params(params, search_dir);
  std::vector<std::string> lens_cameras = optics::eye_model_names();
  if (camera_name == "eye" || std::find(lens_cameras.begin(), lens_cameras.end(), camera_name) != lens_cameras.end())
    return eye_prescription_from_params(camera_name, params, search_dir);
  lens_cameras.insert(lens_cameras.begin(), {"eye", "realistic"});
  std::string list;
  for (const std::string& n : lens_cameras) list += (list.empty() ? "\"" : ", \"") + n + "\"";
  const std::string hint = closest_match(camera_name, lens_cameras);
  throw_error(params.loc(), fmt::format("camera \"{}\" has no lens prescription{}; use one of {}", camera_name,
                                        hint.empty() ? "" : fmt::format(" (did you mean \"{}\"?)", hint), list));
}

}  // namespace eyetrace
