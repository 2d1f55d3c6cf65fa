// `eyetrace check SCENE`: parses and builds a scene without rendering it and lists, compiler
// style, every error (missing files among them) and every warning (what would be ignored or
// approximated), then a summary line. The exit status says whether the scene renders as
// written: 0 nothing to report (or only deprecated forms, read as written), 1 errors (it would
// not render), 3 warnings (it renders, but something in it is ignored). docs/scene-format.md says which errors still
// stop it.
#include <fmt/core.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include "app/commands.h"
#include "scene/parser.h"
#include "scene/scene_builder.h"

namespace eyetrace {

namespace {

struct CheckArgs {
  std::string scene;
  std::string camera;
  bool json = false;
};

constexpr int kExitWarnings = 3;

// Errors and warnings in the order of the scene text (stable: equal places keep their order).
std::vector<Diagnostic> in_file_order(std::vector<Diagnostic> ds) {
  std::stable_sort(ds.begin(), ds.end(), [](const Diagnostic& a, const Diagnostic& b) {
    return std::tie(a.loc.file, a.loc.line, a.loc.column) < std::tie(b.loc.file, b.loc.line, b.loc.column);
  });
  return ds;
}

// Everything the parse and the build report. The build runs on what parsed, with stand-ins
// for a failed film or texture (RenderOverrides::keep_going), so that later errors show too.
std::vector<Diagnostic> check_scene(const CheckArgs& a) {
  DiagnosticList::set_limit(0);
  WarningCollector warnings;
  std::vector<Diagnostic> all;
  ParsedScene parsed = parse_scene_file_collecting(a.scene);
  all = parsed.errors;
  if (parsed.buildable) {
    try {
      RenderOverrides o;
      o.keep_going = true;
      if (!a.camera.empty()) o.camera = parse_directive_text(a.camera, "Camera", "--camera");
      build_render_setup(parsed.desc, o);
    } catch (const SceneError& e) {
      all.insert(all.end(), e.diagnostics().begin(), e.diagnostics().end());
    }
  }
  for (const Diagnostic& w : warnings.warnings()) all.push_back(w);
  return in_file_order(std::move(all));
}

nlohmann::json to_json(const std::string& scene, const std::vector<Diagnostic>& ds) {
  nlohmann::json list = nlohmann::json::array();
  for (const Diagnostic& d : ds)
    list.push_back({{"file", d.loc.file},
                    {"line", d.loc.line},
                    {"column", d.loc.column},
                    {"severity", d.severity == Severity::Error ? "error" : "warning"},
                    {"missing_file", d.kind == DiagnosticKind::MissingFile},
                    {"deprecated", d.kind == DiagnosticKind::Deprecated},
                    {"parameter", d.parameter},
                    {"message", d.message}});
  return {{"scene", scene}, {"diagnostics", list}};
}

int run_check(const CheckArgs& a) {
  const std::vector<Diagnostic> ds = check_scene(a);
  size_t errors = 0, missing = 0, warnings = 0, deprecated = 0;
  for (const Diagnostic& d : ds) {
    if (d.severity == Severity::Warning) ++(d.kind == DiagnosticKind::Deprecated ? deprecated : warnings);
    if (d.severity == Severity::Error) ++errors;
    if (d.kind == DiagnosticKind::MissingFile) ++missing;
  }
  if (a.json) {
    fmt::print("{}\n", to_json(a.scene, ds).dump(2));
  } else {
    for (const Diagnostic& d : ds) fmt::print("{}\n", d.to_string());
    fmt::print("{}: {} error{} ({} missing file{}), {} warning{}{}{}\n", a.scene, errors, errors == 1 ? "" : "s",
               missing, missing == 1 ? "" : "s", warnings, warnings == 1 ? "" : "s",
               deprecated ? fmt::format(" (and {} about deprecated forms)", deprecated) : "",
               errors     ? ": it does not render"
               : warnings ? ": it renders, ignoring what is warned about"
                          : ": ok");
  }
  return errors ? 1 : warnings ? kExitWarnings : 0;
}

const char* kCheckFooter =
    R"(Parses the scene and everything it includes, and creates every plugin it names (reading its
meshes and images) without rendering. Lists every error and every warning, one
`file:line:col: error|warning: ...` line each, in the order of the scene text, then a summary.

Exit status: 0 nothing to report; 1 errors (among them missing files: the scene does not
render); 3 warnings only (it renders, but what is warned about is ignored or approximated);
2 bad command line.)";

}  // namespace

CommandRunner add_check_command(CLI::App& app) {
  auto args = std::make_shared<CheckArgs>();
  CLI::App* c = app.add_subcommand("check", "Check a pbrt-v4 scene file without rendering it");
  c->footer(kCheckFooter);
  c->add_option("scene", args->scene, "Scene file (pbrt-v4 text format)")->required();
  c->add_option("--camera", args->camera, "Check with this Camera directive in place of the scene's");
  c->add_flag("--json", args->json, "Print the diagnostics as JSON (file, line, column, severity, missing_file, ...)");
  return [args] { return run_check(*args); };
}

}  // namespace eyetrace
