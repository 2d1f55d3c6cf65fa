// `eyetrace optics --camera 'Camera "navarro" ...'`: the optics of the eye (or lens) a Camera
// directive describes, without rendering: paraxial constants, pupils and real-ray spot sizes
// as text or JSON, and optionally a spot diagram PNG. The front door of the optics library.
#include <fmt/core.h>

#include <cmath>
#include <limits>
#include <sstream>

#include "app/commands.h"
#include "cameras/lens_system_camera.h"
#include "optics/optics_error.h"
#include "optics/report.h"
#include "optics/spot.h"
#include "render/image_io.h"
#include "scene/parser.h"

namespace eyetrace {

namespace {

struct OpticsArgs {
  std::string camera = "Camera \"navarro\"";
  bool json = false;
  std::string fields = "0,10,20,30,40";
  std::string object_distance;  // metres; empty = infinity
  std::string plot;
  bool strict = false;
};

std::vector<double> parse_fields(const std::string& text) {
  std::vector<double> fields;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    char* end = nullptr;
    const double v = std::strtod(item.c_str(), &end);
    if (item.empty() || end != item.c_str() + item.size() || !std::isfinite(v) || std::abs(v) >= 85.0)
      throw_error(
          fmt::format("--fields \"{}\": expected comma-separated field angles in degrees, each within "
                      "(-85, 85)",
                      text));
    fields.push_back(v);
  }
  if (fields.empty()) throw_error("--fields: give at least one field angle");
  return fields;
}

double parse_distance(const std::string& text) {
  if (text.empty() || text == "inf" || text == "infinity") return std::numeric_limits<double>::infinity();
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || !(v > 0.0))
    throw_error(fmt::format("--object-distance \"{}\": expected a positive distance in metres (or \"inf\")", text));
  return v;
}

// The prescription of the --camera directive. Reading it checks every parameter of the
// directive (view parameters such as fov and mapping too) against the camera's declared ones,
// as render does.
optics::Prescription camera_prescription(const std::string& text) {
  SceneEntity e = parse_directive_text(text, "Camera", "--camera");
  return prescription_from_camera_params(e.name, e.params, ".");
}

// The spot diagram: one panel per field, converted to the linear image write_image expects.
void write_spot_plot(const std::string& path, const optics::Prescription& p, const optics::ReportOptions& o) {
  std::vector<optics::SpotResult> spots;
  for (double field : o.fields_deg) spots.push_back(optics::trace_spot(p, {field, o.object_distance_m, o.spot_grid}));
  const int panel = 256;
  const optics::RgbImage rgb = optics::spot_diagram(spots, panel * static_cast<int>(spots.size()), panel);
  Image image;
  image.width = rgb.width;
  image.height = rgb.height;
  image.pixels.resize(rgb.rgb.size());
  for (size_t i = 0; i < rgb.rgb.size(); ++i) image.pixels[i] = srgb_to_linear(rgb.rgb[i] / 255.f);
  write_image(path, image,
              {{"eyetrace:spot_scale_um_per_pixel", fmt::format("{}", rgb.um_per_pixel)},
               {"eyetrace:scale_bar_um", fmt::format("{}", rgb.scale_bar_um)}});
}

int run_optics(const OpticsArgs& a) {
  set_warnings_fatal(a.strict);
  const optics::Prescription p = camera_prescription(a.camera);
  optics::ReportOptions o;
  o.fields_deg = parse_fields(a.fields);
  o.object_distance_m = parse_distance(a.object_distance);
  try {
    const nlohmann::json report = optics::optics_report(p, o);
    if (a.json)
      fmt::print("{}\n", report.dump(2));
    else
      fmt::print("{}", optics::format_report(report));
    if (!a.plot.empty()) write_spot_plot(a.plot, p, o);
  } catch (const optics::OpticsError& e) {
    throw_error(fmt::format("optics: {}", e.what()));
  }
  if (!a.plot.empty() && !a.json) fmt::print("spot diagram written to {}\n", a.plot);
  return 0;
}

}  // namespace

CommandRunner add_optics_command(CLI::App& app) {
  auto args = std::make_shared<OpticsArgs>();
  CLI::App* c = app.add_subcommand("optics", "Report the optics of an eye or lens camera (no rendering)");
  c->add_option("--camera", args->camera,
                "Camera directive as for render's --camera, e.g. 'Camera \"navarro\" \"float accommodation\" 2' "
                "(default: 'Camera \"navarro\"')");
  c->add_flag("--json", args->json, "Print the report as JSON");
  c->add_flag("--strict", args->strict, "Treat warnings about the camera (e.g. a clamped aperture) as errors");
  c->add_option("--fields", args->fields, "Field angles for real-ray spots, degrees (default 0,10,20,30,40)");
  c->add_option("--object-distance", args->object_distance,
                "Distance of the spot sources in metres from the entrance pupil (default: infinity)");
  c->add_option("--plot", args->plot, "Write a spot diagram image (.png or .exr)");
  return [args] { return run_optics(*args); };
}

}  // namespace eyetrace
