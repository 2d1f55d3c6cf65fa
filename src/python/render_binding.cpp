// eyetrace.render(): a scene file or scene text rendered to a numpy array, through the same
// request and setup as `eyetrace render` (scene/render_request.h) and the same integrator loop;
// the image is the film's, as the command line writes it to EXR (linear float32, top row first).
// The GIL is released while the scene is read, built and rendered. Progress goes to stderr as
// the command line draws it on a terminal. Ctrl-C: the progress callback asks Python for pending
// signals on the calling thread; a KeyboardInterrupt stops the render after the tiles in flight
// and is raised once it has returned.
#include <fmt/core.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <atomic>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <thread>

#include "core/error.h"
#include "python/bindings.h"
#include "render/film.h"
#include "render/image_io.h"
#include "render/integrator.h"
#include "render/progress.h"
#include "scene/parser.h"
#include "scene/render_request.h"

namespace py = pybind11;

namespace eyetrace::python {

namespace {

// resolution=(W, H) or "WxH", as --resolution.
std::string resolution_text(const py::object& r) {
  if (r.is_none()) return "";
  if (py::isinstance<py::str>(r)) return r.cast<std::string>();
  const auto wh = r.cast<std::pair<int, int>>();
  return fmt::format("{}x{}", wh.first, wh.second);
}

// crop=(x0, x1, y0, y1) or "x0,x1,y0,y1", as --crop.
std::string crop_text(const py::object& c) {
  if (c.is_none()) return "";
  if (py::isinstance<py::str>(c)) return c.cast<std::string>();
  const auto v = c.cast<std::vector<double>>();
  std::string s;
  for (double x : v) s += (s.empty() ? "" : ",") + fmt::format("{:.9g}", x);
  return s;
}

// quiet and strict for one render; afterwards warnings print and are not fatal again (the
// module's default, which the Eye calls rely on).
class WarningMode {
 public:
  WarningMode(bool quiet, bool strict) {
    set_warnings_enabled(!quiet);
    set_warnings_fatal(strict);
  }
  ~WarningMode() {
    set_warnings_enabled(true);
    set_warnings_fatal(false);
  }
  WarningMode(const WarningMode&) = delete;
  WarningMode& operator=(const WarningMode&) = delete;
};

// The film's image as an H x W x C float32 array and its channel names.
py::tuple image_array(const Image& image) {
  py::array_t<float> a({py::ssize_t(image.height), py::ssize_t(image.width), py::ssize_t(image.channels)});
  std::copy(image.pixels.begin(), image.pixels.end(), a.mutable_data());
  std::vector<std::string> names = image.channel_names;
  if (names.empty()) names = {"R", "G", "B"};
  return py::make_tuple(a, names);
}

// Paths as str or any os.PathLike (pathlib.Path): pybind11's std::filesystem::path caster.
py::object render(const std::optional<std::filesystem::path>& scene_path, const std::optional<std::string>& text,
                  const std::string& camera, int spp, int64_t seed, int threads, const py::object& resolution,
                  const py::object& crop, bool quiet, bool strict, const std::filesystem::path& search_dir_path,
                  double max_memory_gib, bool channel_names) {
  const std::optional<std::string> scene = scene_path ? std::optional<std::string>(scene_path->string()) : std::nullopt;
  const std::string search_dir = search_dir_path.string();
  if (scene.has_value() == text.has_value()) throw_error("render: give a scene file or text=..., not both or neither");
  if (threads < 0 || threads > 1024)
    throw_parameter_error({}, "--threads", fmt::format("{}: expected 1 to 1024 threads (0: all cores)", threads));
  RenderRequest request;
  request.camera = camera;
  request.resolution = resolution_text(resolution);
  request.crop = crop_text(crop);
  request.spp = spp;
  request.seed = seed;
  request.max_memory_gib = max_memory_gib;
  const WarningMode warnings(quiet, strict);

  std::atomic<bool> stop{false};
  std::shared_ptr<py::error_already_set> signal_error;  // what a Python signal handler raised
  const std::thread::id caller = std::this_thread::get_id();
  Image image;
  {
    py::gil_scoped_release unlocked;
    ProgressLine progress(!quiet);
    const SceneDescription desc = scene ? parse_scene_file(*scene) : parse_scene_string(*text, "<text>", search_dir);
    RenderSetup setup = build_requested_setup(desc, request);
    RenderCounters counters;
    RenderOptions options;
    options.threads = threads;
    options.stop = &stop;
    options.on_progress = [&](double fraction, uint64_t rays) {
      progress.update(fraction, rays);
      // Python runs signal handlers on the main thread only, and needs the GIL to; workers skip.
      if (std::this_thread::get_id() != caller || stop) return;
      py::gil_scoped_acquire locked;
      if (PyErr_CheckSignals() != 0) {
        signal_error = std::make_shared<py::error_already_set>();  // takes the pending exception
        stop = true;
      }
    };
    setup.integrator->render(*setup.camera, *setup.sampler, *setup.film, options, counters);
    progress.finish();
    if (!signal_error) image = setup.film->image();
  }
  if (signal_error) throw *signal_error;
  py::tuple result = image_array(image);
  return channel_names ? py::object(result) : py::object(result[0]);
}

}  // namespace

void bind_render(py::module_& m) {
  m.def("render", &render, py::arg("scene") = py::none(), py::kw_only(), py::arg("text") = py::none(),
        py::arg("camera") = "", py::arg("spp") = 0, py::arg("seed") = -1, py::arg("threads") = 0,
        py::arg("resolution") = py::none(), py::arg("crop") = py::none(), py::arg("quiet") = false,
        py::arg("strict") = false, py::arg("search_dir") = ".", py::arg("max_memory") = 0.0,
        py::arg("channel_names") = false,
        R"(Render a pbrt-v4 scene file (scene=PATH) or scene text (text=..., Include paths relative to search_dir)
as `eyetrace render` does, returning the film's image as a float32 array of shape (height, width, channels):
linear R, G, B and, for a spectral film, its buckets (channel_names=True returns (array, names)).
camera: a Camera directive replacing the scene's (--camera); spp, seed, threads, resolution ((W, H) or
"WxH"), crop ((x0, x1, y0, y1)), max_memory (GiB) as the command line's options (0 / -1 / None: the scene's).
quiet=True: no progress line or warnings; strict=True: warnings are errors. The GIL is released while it
renders. Ctrl-C stops it and raises KeyboardInterrupt.)");
}

}  // namespace eyetrace::python
