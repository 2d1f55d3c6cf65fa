// The subcommands of the eyetrace program; each adds its options to the CLI11 app and
// returns a callback that runs it (and returns the process exit code).
#pragma once
#include <CLI/CLI.hpp>
#include <functional>

namespace eyetrace {

using CommandRunner = std::function<int()>;
CommandRunner add_render_command(CLI::App& app);
CommandRunner add_optics_command(CLI::App& app);
CommandRunner add_plugins_command(CLI::App& app);
CommandRunner add_sweep_command(CLI::App& app);
CommandRunner add_check_command(CLI::App& app);

}  // namespace eyetrace
