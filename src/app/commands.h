// The subcommands of the eyetrace program; each adds its options to the CLI11 app and
// returns a callback that runs it (and returns the process exit code).
#pragma once
#include <CLI/CLI.hpp>
#include <exception>
#include <functional>

namespace eyetrace {

using CommandRunner = std::function<int()>;
CommandRunner add_render_command(CLI::App& app);
CommandRunner add_optics_command(CLI::App& app);
CommandRunner add_plugins_command(CLI::App& app);
CommandRunner add_sweep_command(CLI::App& app);
CommandRunner add_check_command(CLI::App& app);

// Prints an error (a std::exception) as eyetrace reports every error on stderr: a scene error's
// diagnostics one per line, else "error: " and its message. Returns the exit code, 1.
int report_error(const std::exception_ptr& error);

}  // namespace eyetrace
