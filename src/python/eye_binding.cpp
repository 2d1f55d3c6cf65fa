// eyetrace.Eye: the optics of an eye (or a "realistic" lens) from Python. An eye is made the way
// the command line makes it, from a Camera directive (eyetrace optics --camera): keyword
// parameters become the directive's typed parameters, so names, ranges and messages are the eye
// camera's (docs/eye-camera.md). The report is the JSON of `eyetrace optics --json` as a dict;
// spots, wavefront, PSF and MTF come straight from the optics library as numpy arrays.
#include <fmt/core.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "cameras/eye_params.h"
#include "cameras/lens_system_camera.h"
#include "core/error.h"
#include "optics/mtf.h"
#include "optics/optics_error.h"
#include "optics/prescription_io.h"
#include "optics/psf.h"
#include "optics/report.h"
#include "optics/spot.h"
#include "optics/wave_optics_report.h"
#include "optics/wavefront.h"
#include "python/bindings.h"
#include "scene/parser.h"

namespace py = pybind11;

namespace eyetrace::python {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The declared parameters of camera `name`, or null for a name no camera has (the directive's
// reader then reports the unknown camera itself).
const PluginSpec* camera_spec(const std::string& name) {
  if (name == "realistic") return &realistic_camera_spec();
  try {
    return &eye_camera_spec(name);
  } catch (const std::exception&) {
    return nullptr;
  }
}

// A Python value as scene text: strings quoted, booleans true/false, numbers at full precision,
// sequences bracketed.
std::string value_text(const py::handle& v) {
  if (py::isinstance<py::str>(v)) {
    const std::string s = v.cast<std::string>();
    if (s.find('"') != std::string::npos) throw py::value_error(fmt::format("the string {} contains a quote", s));
    return "\"" + s + "\"";
  }
  if (py::isinstance<py::bool_>(v)) return v.cast<bool>() ? "true" : "false";
  if (py::isinstance<py::sequence>(v)) {
    std::string s = "[";
    for (const py::handle& item : v.cast<py::sequence>()) s += (s.size() > 1 ? " " : "") + value_text(item);
    return s + "]";
  }
  try {
    return fmt::format("{:.17g}", v.cast<double>());  // int, float, numpy scalars
  } catch (const py::cast_error&) {
    throw py::type_error(fmt::format("expected a number, string, bool or list of numbers, got {}",
                                     py::str(py::type::of(v)).cast<std::string>()));
  }
}

// The pbrt type a keyword parameter is written with: the declared one, or else what the Python
// value is (an undeclared name is then reported by the directive's reader, with a suggestion).
std::string type_text(const PluginSpec* spec, const std::string& name, const py::handle& v) {
  if (const ParamSpec* p = spec ? spec->find(name) : nullptr) return p->accepted_types().front();
  if (py::isinstance<py::str>(v)) return "string";
  if (py::isinstance<py::bool_>(v)) return "bool";
  return "float";
}

// Camera "name" "type parameter" value ... for Eye(name, **params).
std::string camera_directive(const std::string& name, const py::kwargs& params) {
  const PluginSpec* spec = camera_spec(name);
  std::string text = fmt::format("Camera \"{}\"", name);
  for (const auto& [key, value] : params) {
    const std::string parameter = key.cast<std::string>();
    try {
      text += fmt::format(" \"{} {}\" {}", type_text(spec, parameter, value), parameter, value_text(value));
    } catch (const py::type_error& e) {
      throw py::type_error(fmt::format("Eye parameter '{}': {}", parameter, e.what()));
    } catch (const py::value_error& e) {
      throw py::value_error(fmt::format("Eye parameter '{}': {}", parameter, e.what()));
    }
  }
  return text;
}

struct Eye {
  std::string camera;  // the Camera directive, or "" for a prescription file
  std::string prescription_file;
  optics::Prescription prescription;
};

Eye eye_from_camera(const std::string& directive) {
  // As `eyetrace optics --camera` (optics_command.cpp): every parameter checked against the
  // camera's declared ones, lens files relative to the working directory.
  SceneEntity e = parse_directive_text(directive, "Camera", "--camera");
  return Eye{directive, "", prescription_from_camera_params(e.name, e.params, ".")};
}

// path: str or any os.PathLike (pathlib.Path).
Eye eye_from_prescription(const std::filesystem::path& file) {
  const std::string path = file.string();
  try {
    return Eye{"", path, optics::load_prescription_file(path)};
  } catch (const optics::OpticsError& e) {
    throw_error(fmt::format("--prescription: {}", e.what()));  // the command line's wording
  }
}

// Runs an optics computation, its OpticsError worded as `eyetrace optics` words it.
template <typename F>
auto optics_call(F&& f) {
  try {
    return f();
  } catch (const optics::OpticsError& e) {
    throw_error(fmt::format("optics: {}", e.what()));
  }
}

optics::WavefrontOptions wave_options(double field, std::optional<double> wavelength,
                                      std::optional<double> pupil_diameter, int grid, int zernike_order,
                                      double object_distance) {
  optics::WavefrontOptions o;
  o.field_deg = field;
  o.object_distance_m = object_distance;
  if (wavelength) o.wavelength_nm = *wavelength;
  if (pupil_diameter) o.pupil_radius_mm = 0.5 * *pupil_diameter;
  o.grid = grid;
  o.zernike_order = zernike_order;
  optics_call([&] {
    optics::validate(o);
    return 0;
  });
  return o;
}

py::dict power_vector(const optics::PowerVector& p) {
  py::dict d;
  d["M_diopters"] = p.M_D;
  d["J0_diopters"] = p.J0_D;
  d["J45_diopters"] = p.J45_D;
  return d;
}

py::array_t<double> points_array(const std::vector<glm::dvec2>& points) {
  py::array_t<double> a({py::ssize_t(points.size()), py::ssize_t(2)});
  auto w = a.mutable_unchecked<2>();
  for (size_t i = 0; i < points.size(); ++i) w(py::ssize_t(i), 0) = points[i].x, w(py::ssize_t(i), 1) = points[i].y;
  return a;
}

py::dict report(const Eye& eye, const std::vector<double>& fields, double object_distance, bool wave,
                std::optional<double> wave_pupil, std::optional<double> wave_wavelength, int wave_grid,
                int zernike_order, const std::vector<double>& freqs, bool polychromatic) {
  optics::ReportOptions o;
  o.fields_deg = fields;
  o.object_distance_m = object_distance;
  o.wave = wave;
  o.wave_options = wave_options(0.0, wave_wavelength, wave_pupil, wave_grid, zernike_order, kInfinity);
  o.mtf_freqs_cpd = freqs;
  o.polychromatic = polychromatic;
  if (fields.empty()) throw_error("fields: give at least one field angle");
  if (polychromatic && !wave) throw_error("polychromatic: give wave=True too (it adds to the wave section)");
  const std::string text = optics_call([&] {
    if (o.wave) optics::check_mtf_frequencies(eye.prescription, o.wave_options, o.mtf_freqs_cpd);
    py::gil_scoped_release unlocked;  // pure C++ from here: other Python threads may run
    return optics::optics_report(eye.prescription, o).dump();
  });
  // The JSON text of `eyetrace optics --json`, read by Python's own json module.
  return py::module_::import("json").attr("loads")(text);
}

py::dict spot(const Eye& eye, double field, double object_distance, int grid) {
  const optics::SpotResult s = optics_call([&] {
    py::gil_scoped_release unlocked;
    return optics::trace_spot(eye.prescription, {field, object_distance, grid});
  });
  py::dict d;
  d["field_deg"] = s.field_deg;
  d["rays"] = s.rays;
  d["rays_launched"] = s.rays_launched;
  d["rms_radius_um"] = s.rms_radius_um;
  d["ee50_radius_um"] = s.ee50_radius_um;
  d["centroid_mm"] = py::make_tuple(s.centroid_mm.x, s.centroid_mm.y, s.centroid_mm.z);
  d["points_um"] = points_array(s.points_um);
  return d;
}

py::dict wavefront(const Eye& eye, double field, std::optional<double> wavelength, std::optional<double> pupil_diameter,
                   int grid, int zernike_order, double object_distance) {
  const optics::WavefrontOptions o =
      wave_options(field, wavelength, pupil_diameter, grid, zernike_order, object_distance);
  const optics::WavefrontResult w = optics_call([&] {
    py::gil_scoped_release unlocked;
    return optics::trace_wavefront(eye.prescription, o);
  });
  py::dict d;
  d["field_deg"] = w.field_deg;
  d["wavelength_nm"] = w.wavelength_nm;
  d["pupil_radius_mm"] = w.pupil_radius_mm;
  d["zernike_order"] = w.zernike_order;
  d["zernike_osa_um"] = py::array_t<double>(py::ssize_t(w.zernike_um.size()), w.zernike_um.data());
  d["pupil_points"] = points_array(w.pupil_points);
  d["opd_waves"] = py::array_t<double>(py::ssize_t(w.opd_waves.size()), w.opd_waves.data());
  d["rms_waves"] = w.rms_waves;
  d["rms_sampled_waves"] = w.rms_sampled_waves;
  d["pv_waves"] = w.pv_waves;
  d["refraction"] = py::dict(py::arg("least_squares") = power_vector(w.least_squares),
                             py::arg("paraxial") = power_vector(w.paraxial));
  d["rays"] = w.rays_in_pupil;
  d["rays_lost"] = w.rays_lost;
  d["warning"] = w.warning;
  return d;
}

optics::TracedPsf traced_psf(const Eye& eye, double field, std::optional<double> wavelength,
                             std::optional<double> pupil_diameter, int grid, double object_distance) {
  optics::WavefrontOptions o = wave_options(field, wavelength, pupil_diameter, grid, 6, object_distance);
  return optics_call([&] {
    py::gil_scoped_release unlocked;
    return optics::trace_psf(eye.prescription, o);
  });
}

py::dict psf(const Eye& eye, double field, std::optional<double> wavelength, std::optional<double> pupil_diameter,
             int grid, double object_distance) {
  const optics::Psf p = traced_psf(eye, field, wavelength, pupil_diameter, grid, object_distance).psf;
  py::dict d;
  py::array_t<double> intensity({py::ssize_t(p.fft_size), py::ssize_t(p.fft_size)});
  std::copy(p.intensity.begin(), p.intensity.end(), intensity.mutable_data());
  d["intensity"] = intensity;
  d["wavelength_nm"] = p.wavelength_nm;
  d["pupil_radius_mm"] = p.pupil_radius_mm;
  d["grid"] = p.grid;
  d["sample_x_rad"] = p.sample_x_rad;
  d["sample_y_rad"] = p.sample_y_rad;
  d["sample_x_um"] = p.sample_x_um;
  d["sample_y_um"] = p.sample_y_um;
  d["strehl"] = p.strehl;
  d["ee50_um"] = p.ee50_um;
  d["ee80_um"] = p.ee80_um;
  d["warning"] = p.warning;
  return d;
}

py::dict mtf(const Eye& eye, const std::vector<double>& freqs, double field, std::optional<double> wavelength,
             std::optional<double> pupil_diameter, int grid, double object_distance) {
  const optics::Psf p = traced_psf(eye, field, wavelength, pupil_diameter, grid, object_distance).psf;
  const std::vector<optics::MtfPoint> points = optics_call([&] { return optics::compute_mtf(p, freqs); });
  std::vector<double> t, s;
  for (const optics::MtfPoint& m : points) t.push_back(m.tangential), s.push_back(m.sagittal);
  py::dict d;
  d["freq_cpd"] = py::array_t<double>(py::ssize_t(freqs.size()), freqs.data());
  d["tangential"] = py::array_t<double>(py::ssize_t(t.size()), t.data());
  d["sagittal"] = py::array_t<double>(py::ssize_t(s.size()), s.data());
  d["sagittal_cutoff_cpd"] = optics::sagittal_cutoff_cpd(p);
  d["tangential_cutoff_cpd"] = optics::tangential_cutoff_cpd(p);
  return d;
}

}  // namespace

void bind_eye(py::module_& m) {
  const std::vector<double> default_fields = optics::ReportOptions{}.fields_deg;
  const std::vector<double> default_freqs = optics::ReportOptions{}.mtf_freqs_cpd;
  py::class_<Eye>(m, "Eye",
                  "An eye (or a \"realistic\" lens): Eye(\"navarro\", pupildiameter=4, accommodation=2) takes a "
                  "camera name (Eye(\"eye\", model=\"navarro\") too) and the eye camera's parameters "
                  "(docs/eye-camera.md) as keywords; Eye.from_camera(directive) and "
                  "Eye.from_prescription(path) as `eyetrace optics --camera` and `--prescription`.")
      .def(py::init([](const std::string& name, const py::kwargs& params) {
             return eye_from_camera(camera_directive(name, params));
           }),
           py::arg("name") = "navarro")
      .def_static("from_camera", &eye_from_camera, py::arg("directive"),
                  "An eye from a Camera directive, e.g. 'Camera \"navarro\" \"float accommodation\" 2'")
      .def_static("from_prescription", &eye_from_prescription, py::arg("path"),
                  "An eye from a prescription JSON file (docs/eye-models.md)")
      .def_property_readonly(
          "camera", [](const Eye& e) { return e.camera; }, "The Camera directive (\"\" for a prescription file)")
      .def_property_readonly(
          "name", [](const Eye& e) { return e.prescription.name; }, "The model's name")
      .def("__repr__",
           [](const Eye& e) {
             return e.camera.empty() ? fmt::format("eyetrace.Eye.from_prescription('{}')", e.prescription_file)
                                     : fmt::format("eyetrace.Eye.from_camera('{}')", e.camera);
           })
      .def("report", &report, py::arg("fields") = default_fields, py::arg("object_distance") = kInfinity,
           py::arg("wave") = false, py::arg("wave_pupil") = py::none(), py::arg("wave_wavelength") = py::none(),
           py::arg("wave_grid") = 64, py::arg("zernike_order") = 6, py::arg("freqs") = default_freqs,
           py::arg("polychromatic") = false,
           "The optics report as a dict: the JSON of `eyetrace optics --json` (keys as docs/eye-models.md and "
           "src/optics/report.h). wave_pupil is a diameter in mm, wave_wavelength in nm, object_distance in m.")
      .def("spot", &spot, py::arg("field") = 0.0, py::arg("object_distance") = kInfinity, py::arg("grid") = 64,
           "The real-ray spot of a point source: points_um (N x 2 array, um from the centroid), rms_radius_um, ...")
      .def("wavefront", &wavefront, py::arg("field") = 0.0, py::arg("wavelength") = py::none(),
           py::arg("pupil_diameter") = py::none(), py::arg("grid") = 64, py::arg("zernike_order") = 6,
           py::arg("object_distance") = kInfinity,
           "The wavefront: zernike_osa_um (OSA/ANSI c_j in um), pupil_points and opd_waves (arrays), rms_waves, "
           "refraction (power vectors), ...")
      .def("psf", &psf, py::arg("field") = 0.0, py::arg("wavelength") = py::none(),
           py::arg("pupil_diameter") = py::none(), py::arg("grid") = 64, py::arg("object_distance") = kInfinity,
           "The diffraction PSF: intensity (N x N array, rows y, in units of the diffraction-limited peak), "
           "sample_x_um / sample_y_um, strehl, ee50_um, ee80_um, ...")
      .def("mtf", &mtf, py::arg("freqs"), py::arg("field") = 0.0, py::arg("wavelength") = py::none(),
           py::arg("pupil_diameter") = py::none(), py::arg("grid") = 64, py::arg("object_distance") = kInfinity,
           "The MTF at frequencies in cycles per degree: freq_cpd, tangential, sagittal (arrays), cut-offs");
}

}  // namespace eyetrace::python
