// eyetrace: render pbrt-v4 scenes through pinhole, thin-lens and schematic-eye cameras.
#include <exception>

#include "app/commands.h"

int main(int argc, char** argv) {
  CLI::App app{
      "eyetrace: a physically based renderer that shows what a human eye sees.\n"
      "Renders pbrt-v4 scene files through pinhole, thin-lens and schematic-eye cameras."};
  app.require_subcommand(1);
  auto render = eyetrace::add_render_command(app);
  auto optics = eyetrace::add_optics_command(app);
  auto plugins = eyetrace::add_plugins_command(app);
  auto sweep = eyetrace::add_sweep_command(app);
  auto check = eyetrace::add_check_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // CLI11 has an exit code per kind of mistake (105, 106, ...); eyetrace documents one:
    // 2 for any bad command line (0 for --help).
    return app.exit(e) == 0 ? 0 : 2;
  }
  try {
    if (app.got_subcommand("render")) return render();
    if (app.got_subcommand("optics")) return optics();
    if (app.got_subcommand("plugins")) return plugins();
    if (app.got_subcommand("sweep")) return sweep();
    if (app.got_subcommand("check")) return check();
  } catch (const std::exception&) {
    return eyetrace::report_error(std::current_exception());
  }
  return 0;
}
