// `eyetrace optics --camera 'Camera "navarro" ...'`: the optics of the eye (or lens) a Camera
// directive describes, without rendering: paraxial constants, pupils, real-ray spot sizes and
// chromatic aberration (dispersion laws, chromatic difference of refraction, transverse
// chromatic aberration) and, with --wave, the wavefront (OPD, Zernike coefficients, refraction)
// and its diffraction (PSF's Strehl ratio and encircled energy, MTF) as text or JSON, and optionally a figure (spot
// diagram above the refraction-vs-wavelength curve). The front door of the optics library.
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <tuple>

#include "app/commands.h"
#include "cameras/lens_system_camera.h"
#include "core/srgb.h"
#include "optics/optics_error.h"
#include "optics/prescription_io.h"
#include "optics/report.h"
#include "optics/spot.h"
#include "optics/wave_optics_report.h"
#include "optics/wave_plot.h"
#include "render/image_io.h"
#include "scene/parser.h"

namespace eyetrace {

namespace {

struct OpticsArgs {
  std::string camera;        // empty: 'Camera "navarro"'
  std::string prescription;  // a prescription JSON file instead of a camera
  bool json = false;
  std::string fields = "0,10,20,30,40";
  std::string object_distance;  // metres; empty = infinity
  std::string plot;
  bool strict = false;
  std::string chromatic_range = "400,700";  // nm
  std::string chromatic_step;               // nm; empty = 10, or the range's width if smaller
  std::string tca_wavelengths = "450,650";  // nm
  bool wave = false;
  std::string wave_pupil;       // entrance-pupil diameter, mm; empty = the paraxial entrance pupil
  std::string wave_wavelength;  // nm; empty = the camera's
  std::string wave_grid = "64";
  std::string zernike_order = "6";
  std::string freqs = "5,10,20,30,40,60";  // MTF frequencies, cycles per degree
  bool polychromatic = false;
  std::string poly_range = "400,700";  // nm
  std::string poly_step = "10";        // nm
  std::string poly_source = "equal";   // equal | blackbody:KELVIN
  std::string psf_scale = "log";       // the PSF image of --plot DIR: log | linear
};

// The number `text` spells, whole (strtod's reading, so "inf" and "nan" too); none when it is
// empty or has anything after the number. Callers add their own range checks.
std::optional<double> to_number(const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size()) return std::nullopt;
  return v;
}

// Comma-separated numbers, each accepted by `ok`; otherwise (or when there are none) an error.
template <typename Ok>
std::vector<double> parse_list(const std::string& text, Ok ok, const std::string& bad, const std::string& none) {
  std::vector<double> values;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) {
    const std::optional<double> v = to_number(item);
    if (!v || !std::isfinite(*v) || !ok(*v)) throw_error(bad);
    values.push_back(*v);
  }
  if (values.empty()) throw_error(none);
  return values;
}

std::vector<double> parse_fields(const std::string& text) {
  return parse_list(
      text, [](double v) { return std::abs(v) < 85.0; },
      fmt::format("--fields \"{}\": expected comma-separated field angles in degrees, each within (-85, 85)", text),
      "--fields: give at least one field angle");
}

// Comma-separated MTF frequencies in cycles per degree, each finite and >= 0.
std::vector<double> parse_freqs(const std::string& text) {
  return parse_list(
      text, [](double v) { return v >= 0.0; },
      fmt::format("--freqs \"{}\": expected comma-separated frequencies in cycles/deg, each >= 0", text),
      "--freqs: give at least one frequency");
}

double parse_distance(const std::string& text) {
  if (text.empty() || text == "inf" || text == "infinity") return std::numeric_limits<double>::infinity();
  const std::optional<double> v = to_number(text);
  if (!v || !(*v > 0.0))
    throw_error(fmt::format("--object-distance \"{}\": expected a positive distance in metres (or \"inf\")", text));
  return *v;
}

// Two comma-separated numbers.
std::pair<double, double> parse_pair(const char* flag, const std::string& text) {
  const size_t comma = text.find(',');
  const std::optional<double> x = to_number(text.substr(0, comma)),
                              y = comma == std::string::npos ? std::nullopt : to_number(text.substr(comma + 1));
  if (!x || !y || !std::isfinite(*x) || !std::isfinite(*y))
    throw_error(fmt::format("{} \"{}\": expected two wavelengths in nm, e.g. 400,700", flag, text));
  return {*x, *y};
}

// Options as they stand after `flag` was read: optics::validate's complaint, if any, naming the flag.
template <typename Options>
void check_flag(const char* flag, const std::string& text, const Options& o) {
  try {
    optics::validate(o);
  } catch (const optics::OpticsError& e) {
    throw_error(fmt::format("{} \"{}\": {}", flag, text, e.what()));
  }
}

// The chromatic options of the three flags; each flag is checked on its own so the error names it.
optics::ChromaticOptions parse_chromatic(const OpticsArgs& a) {
  optics::ChromaticOptions o;
  optics::ChromaticOptions range;
  std::tie(range.min_wavelength_nm, range.max_wavelength_nm) = parse_pair("--chromatic-range", a.chromatic_range);
  range.step_nm = std::min(range.step_nm, std::abs(range.max_wavelength_nm - range.min_wavelength_nm));
  check_flag("--chromatic-range", a.chromatic_range, range);
  o.min_wavelength_nm = range.min_wavelength_nm, o.max_wavelength_nm = range.max_wavelength_nm;
  o.step_nm = range.step_nm;
  if (!a.chromatic_step.empty()) {
    const std::optional<double> step = to_number(a.chromatic_step);
    if (!step) throw_error(fmt::format("--chromatic-step \"{}\": expected a step in nm, e.g. 10", a.chromatic_step));
    o.step_nm = *step;
    check_flag("--chromatic-step", a.chromatic_step, o);
  }
  std::tie(o.tca_short_nm, o.tca_long_nm) = parse_pair("--tca-wavelengths", a.tca_wavelengths);
  check_flag("--tca-wavelengths", a.tca_wavelengths, o);
  return o;
}

// The wavefront options of their flags, each checked on its own so the error names it.
optics::WavefrontOptions parse_wave(const OpticsArgs& a) {
  optics::WavefrontOptions o;
  auto number = [](const char* flag, const std::string& text, const char* example) {
    const std::optional<double> v = to_number(text);
    if (!v || !std::isfinite(*v)) throw_error(fmt::format("{} \"{}\": expected {}", flag, text, example));
    return *v;
  };
  // A whole number of samples or a radial order; anything else becomes 0, which validate refuses.
  auto whole = [](double v) { return v == std::floor(v) && std::abs(v) < 1e6 ? static_cast<int>(v) : 0; };
  if (!a.wave_pupil.empty()) {
    o.pupil_radius_mm = 0.5 * number("--wave-pupil", a.wave_pupil, "an entrance-pupil diameter in mm, e.g. 6");
    if (!(o.pupil_radius_mm > 0.0)) throw_error(fmt::format("--wave-pupil \"{}\": must be > 0 mm", a.wave_pupil));
    check_flag("--wave-pupil", a.wave_pupil, o);
  }
  if (!a.wave_wavelength.empty()) {
    o.wavelength_nm = number("--wave-wavelength", a.wave_wavelength, "a wavelength in nm, e.g. 555");
    if (o.wavelength_nm == 0.0) throw_error("--wave-wavelength \"0\": give a wavelength in nm");
    check_flag("--wave-wavelength", a.wave_wavelength, o);
  }
  o.grid = whole(number("--wave-grid", a.wave_grid, "a number of samples across the pupil, e.g. 64"));
  check_flag("--wave-grid", a.wave_grid, o);
  o.zernike_order = whole(number("--zernike-order", a.zernike_order, "a radial order, e.g. 6"));
  check_flag("--zernike-order", a.zernike_order, o);
  return o;
}

// Planck's law, relative spectral radiance per nm at a temperature (the constant factors cancel
// in the normalised weights).
std::function<double(double)> blackbody(double kelvin) {
  return [kelvin](double nm) {
    const double c2 = 1.438776877e7;  // h c / k in nm K (CODATA 2018)
    return std::pow(nm / 500.0, -5.0) / std::expm1(c2 / (nm * kelvin));
  };
}

// The polychromatic options of their flags, each checked on its own so the error names it.
optics::PolychromaticOptions parse_polychromatic(const OpticsArgs& a) {
  optics::PolychromaticOptions o;
  std::tie(o.min_wavelength_nm, o.max_wavelength_nm) = parse_pair("--poly-range", a.poly_range);
  o.step_nm = std::min(o.step_nm, std::abs(o.max_wavelength_nm - o.min_wavelength_nm));
  check_flag("--poly-range", a.poly_range, o);
  const std::optional<double> step = to_number(a.poly_step);
  if (!step) throw_error(fmt::format("--poly-step \"{}\": expected a step in nm, e.g. 10", a.poly_step));
  o.step_nm = *step;
  check_flag("--poly-step", a.poly_step, o);
  if (a.poly_source.rfind("blackbody:", 0) == 0) {
    const std::optional<double> kelvin = to_number(a.poly_source.substr(10));
    if (!kelvin || !(*kelvin >= 500.0 && *kelvin <= 1e5))
      throw_error(
          fmt::format("--poly-source \"{}\": expected blackbody:KELVIN with 500 <= KELVIN <= 100000", a.poly_source));
    o.source = blackbody(*kelvin);
    o.source_name = fmt::format("blackbody {:g} K", *kelvin);
  } else if (a.poly_source != "equal") {
    throw_error(
        fmt::format("--poly-source \"{}\": expected \"equal\" (equal energy) or blackbody:KELVIN", a.poly_source));
  }
  return o;
}

// The prescription of the --camera directive. Reading it checks every parameter of the
// directive (view parameters such as fov and mapping too) against the camera's declared ones,
// as render does.
optics::Prescription camera_prescription(const std::string& text) {
  SceneEntity e = parse_directive_text(text, "Camera", "--camera");
  return prescription_from_camera_params(e.name, e.params, ".");
}

// An RGB figure as the linear image write_image expects.
void write_rgb(const std::string& path, const optics::RgbImage& rgb,
               const std::map<std::string, std::string>& attributes) {
  Image image;
  image.width = rgb.width;
  image.height = rgb.height;
  image.pixels.resize(rgb.rgb.size());
  for (size_t i = 0; i < rgb.rgb.size(); ++i) image.pixels[i] = srgb_to_linear(rgb.rgb[i] / 255.f);
  write_image(path, image, attributes);
}

// The figure: the spot diagram (one panel per field) above the chromatic refraction curve.
void write_plot(const std::string& path, const optics::Prescription& p, const optics::ReportOptions& o,
                const nlohmann::json& report) {
  std::vector<optics::SpotResult> spots;
  for (double field : o.fields_deg) spots.push_back(optics::trace_spot(p, {field, o.object_distance_m, o.spot_grid}));
  const int panel = 256;
  const optics::RgbImage spot = optics::spot_diagram(spots, panel * static_cast<int>(spots.size()), panel);
  const optics::RgbImage curve = optics::chromatic_plot(report, std::max(spot.width, 720), 400);
  optics::RgbImage rgb(std::max(spot.width, curve.width), spot.height + curve.height);
  rgb.blit(spot, (rgb.width - spot.width) / 2, 0);
  rgb.blit(curve, 0, spot.height);
  write_rgb(path, rgb,
            {{"eyetrace:spot_scale_um_per_pixel", fmt::format("{}", spot.um_per_pixel)},
             {"eyetrace:scale_bar_um", fmt::format("{}", spot.scale_bar_um)},
             {"eyetrace:spot_diagram_height", fmt::format("{}", spot.height)},
             {"eyetrace:lca_diopters", report["chromatic"]["lca_diopters"].dump()}});
}

// --plot names a file (.png or .exr: the spot and chromatic figure) or else a directory, created
// if missing, for that figure and the wave figures. Checked before the analysis runs.
bool is_plot_directory(const std::string& path) {
  const std::string ext = std::filesystem::path(path).extension().string();
  return !(ext == ".png" || ext == ".exr" || ext == ".PNG" || ext == ".EXR");
}

void prepare_plot_directory(const std::string& dir) {
  std::error_code ec;
  if (std::filesystem::exists(dir, ec) && !std::filesystem::is_directory(dir, ec))
    throw_error(
        fmt::format("--plot \"{}\": exists and is not a directory (give a directory for the figures, or a "
                    ".png/.exr file for the spot diagram alone)",
                    dir));
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir))
    throw_error(fmt::format("--plot \"{}\": cannot create the directory: {}", dir, ec ? ec.message() : "unknown"));
}

// One figure per analysed field: DIR/wave_field_<deg>.png (MTF curves and the PSF, wave_plot.h),
// the PSF traced again as the report traced it (trace_psf).
std::vector<std::string> write_wave_plots(const std::string& dir, const optics::Prescription& p,
                                          const optics::ReportOptions& o, const nlohmann::json& report, bool log_psf) {
  std::vector<std::string> written;
  for (const nlohmann::json& f : report["wave"]) {
    if (f.contains("error")) continue;  // the text and JSON say why
    optics::WavefrontOptions w = o.wave_options;
    w.field_deg = f["field_deg"].get<double>();
    w.object_distance_m = o.object_distance_m;
    const optics::TracedPsf traced = optics::trace_psf(p, w);
    std::vector<optics::MtfPoint> markers;
    if (f.contains("polychromatic") && f["polychromatic"].contains("mtf"))
      for (const nlohmann::json& m : f["polychromatic"]["mtf"]) {
        optics::MtfPoint point;
        point.freq_cpd = m["freq_cpd"].get<double>();
        point.tangential = m["tangential"].get<double>(), point.sagittal = m["sagittal"].get<double>();
        markers.push_back(point);
      }
    const std::string title =
        fmt::format("{} field {:g} deg, {:g} nm, pupil {:.2f} mm: Strehl {:.3f}, EE50 {:.1f} um, EE80 {:.1f} um",
                    report.value("model", ""), w.field_deg, traced.psf.wavelength_nm, 2.0 * traced.psf.pupil_radius_mm,
                    traced.psf.strehl, traced.psf.ee50_um, traced.psf.ee80_um);
    const std::string path = (std::filesystem::path(dir) / fmt::format("wave_field_{:g}.png", w.field_deg)).string();
    optics::WavePlotOptions options;
    options.log_psf = log_psf;
    write_rgb(path, optics::wave_figure(traced.psf, markers, title, options),
              {{"eyetrace:field_deg", fmt::format("{:g}", w.field_deg)},
               {"eyetrace:strehl", fmt::format("{}", traced.psf.strehl)},
               {"eyetrace:psf_scale", log_psf ? "log" : "linear"}});
    written.push_back(path);
  }
  return written;
}

int run_optics(const OpticsArgs& a) {
  set_warnings_fatal(a.strict);
  if (!a.camera.empty() && !a.prescription.empty()) throw_error("give --camera or --prescription, not both");
  optics::Prescription p;
  if (a.prescription.empty()) {
    p = camera_prescription(a.camera.empty() ? "Camera \"navarro\"" : a.camera);
  } else {
    try {
      p = optics::load_prescription_file(a.prescription);
    } catch (const optics::OpticsError& e) {
      throw_error(fmt::format("--prescription: {}", e.what()));
    }
  }
  optics::ReportOptions o;
  o.fields_deg = parse_fields(a.fields);
  o.object_distance_m = parse_distance(a.object_distance);
  o.chromatic = parse_chromatic(a);
  o.wave = a.wave;
  o.wave_options = parse_wave(a);
  o.mtf_freqs_cpd = parse_freqs(a.freqs);
  o.polychromatic = a.polychromatic;
  o.polychromatic_options = parse_polychromatic(a);
  if (o.polychromatic && !o.wave) throw_error("--polychromatic: give --wave too (it adds to the wave section)");
  if (a.psf_scale != "log" && a.psf_scale != "linear")
    throw_error(fmt::format("--psf-scale \"{}\": expected log or linear", a.psf_scale));
  const bool plot_directory = !a.plot.empty() && is_plot_directory(a.plot);
  if (plot_directory) prepare_plot_directory(a.plot);
  std::vector<std::string> written;
  if (o.wave) try {
      optics::check_mtf_frequencies(p, o.wave_options, o.mtf_freqs_cpd);
    } catch (const optics::OpticsError& e) {
      throw_error(fmt::format("--freqs \"{}\": {}", a.freqs, e.what()));
    }
  try {
    const nlohmann::json report = optics::optics_report(p, o);
    if (a.json)
      fmt::print("{}\n", report.dump(2));
    else
      fmt::print("{}", optics::format_report(report));
    if (plot_directory) {
      written.push_back((std::filesystem::path(a.plot) / "spots.png").string());
      write_plot(written.back(), p, o, report);
      if (o.wave) {
        const std::vector<std::string> wave = write_wave_plots(a.plot, p, o, report, a.psf_scale == "log");
        written.insert(written.end(), wave.begin(), wave.end());
      }
    } else if (!a.plot.empty()) {
      write_plot(a.plot, p, o, report);
      written.push_back(a.plot);
    }
  } catch (const optics::OpticsError& e) {
    throw_error(fmt::format("optics: {}", e.what()));
  }
  if (!a.json)
    for (const std::string& path : written) fmt::print("figure written to {}\n", path);
  return 0;
}

}  // namespace

CommandRunner add_optics_command(CLI::App& app) {
  auto args = std::make_shared<OpticsArgs>();
  CLI::App* c = app.add_subcommand("optics", "Report the optics of an eye or lens camera (no rendering)");
  c->add_option("--camera", args->camera,
                "Camera directive as for render's --camera, e.g. 'Camera \"navarro\" \"float accommodation\" 2' "
                "(default: 'Camera \"navarro\"')");
  c->add_option("--prescription", args->prescription,
                "A prescription JSON file (docs/eye-models.md: the data/eyes format, with optional biconic, "
                "tilted and decentred surfaces) instead of --camera");
  c->add_flag("--json", args->json, "Print the report as JSON");
  c->add_flag("--strict", args->strict, "Treat warnings about the camera (e.g. a clamped aperture) as errors");
  c->add_option("--fields", args->fields, "Field angles for real-ray spots, degrees (default 0,10,20,30,40)");
  c->add_option("--object-distance", args->object_distance,
                "Distance of the spot sources in metres from the entrance pupil (default: infinity)");
  c->add_option(
      "--plot", args->plot,
      "A .png or .exr file: the spot diagram above the refraction-vs-wavelength curve; any other path: a "
      "directory (created) for that figure (spots.png) and, with --wave, one figure per field "
      "(wave_field_<deg>.png: MTF in cycles/deg with the diffraction limit, and the PSF in um on the retina)");
  c->add_option("--psf-scale", args->psf_scale, "The PSF image of --plot DIR: log (3 decades, default) or linear");
  c->add_option("--chromatic-range", args->chromatic_range,
                "Wavelengths of the chromatic difference of refraction, nm: MIN,MAX (default 400,700; within "
                "[360, 1020], where the dispersion laws are used)");
  c->add_option("--chromatic-step", args->chromatic_step,
                "Step of the chromatic refraction list, nm (default 10, or the range's width if smaller)");
  c->add_option("--tca-wavelengths", args->tca_wavelengths,
                "Transverse chromatic aberration between these wavelengths, nm: SHORT,LONG (default 450,650)");
  c->add_flag("--wave", args->wave,
              "Add the wavefront at each field of --fields (JSON key `wave`): RMS and PV in waves, OSA Zernike "
              "coefficients in um, refraction from the wavefront, Strehl ratio, encircled energy and MTF of the "
              "PSF (docs/wavefront.md)");
  c->add_option("--wave-pupil", args->wave_pupil,
                "Entrance-pupil diameter of the wavefront analysis, mm (default: the paraxial entrance pupil)");
  c->add_option("--wave-wavelength", args->wave_wavelength,
                "Wavelength of the wavefront analysis, nm (default: the "
                "camera's)");
  c->add_option("--wave-grid", args->wave_grid, "Samples across the pupil of the wavefront analysis (default 64)");
  c->add_option("--zernike-order", args->zernike_order, "Highest radial order of the Zernike fit (default 6)");
  c->add_option("--freqs", args->freqs,
                "MTF frequencies of --wave, cycles per degree of visual angle (default 5,10,20,30,40,60; each "
                "within the diffraction cut-off D / wavelength)");
  c->add_flag("--polychromatic", args->polychromatic,
              "With --wave: add per field the polychromatic PSF's Strehl ratio, encircled energy and MTF, the "
              "wavelengths of --poly-range weighted by V(lambda) x the source (JSON key `polychromatic`)");
  c->add_option("--poly-range", args->poly_range,
                "Wavelengths of --polychromatic, nm: MIN,MAX (default 400,700; within [380, 780])");
  c->add_option("--poly-step", args->poly_step, "Step between the wavelengths of --polychromatic, nm (default 10)");
  c->add_option("--poly-source", args->poly_source,
                "Source spectrum of --polychromatic: equal (equal energy, the default) or blackbody:KELVIN");
  return [args] { return run_optics(*args); };
}

}  // namespace eyetrace
