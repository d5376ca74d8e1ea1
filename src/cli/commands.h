// diffuv tool: the subcommands, one file each. Only the tool prints.
#ifndef DIFFUV_CLI_COMMANDS_H
#define DIFFUV_CLI_COMMANDS_H

#include <CLI/CLI.hpp>

namespace diffuv_cli {

/// Exit codes of the tool.
enum Exit_code : int {
  exit_ok = 0,
  exit_bad_input = 1,   ///< a file that cannot be read, parsed, or used (not a disc, bad corners, ...)
  exit_usage = 2,       ///< wrong command line
  exit_output = 3,      ///< an output that cannot be written
  exit_internal = 4     ///< an unexpected failure (a bug: please report it)
};

/// Registers `diffuv param`; its callback runs the command.
void add_param_command(CLI::App& app);

/// Registers `diffuv render` (in param.cpp: the same pipeline, a picture only).
void add_render_command(CLI::App& app);

/// Registers `diffuv compare`.
void add_compare_command(CLI::App& app);

/// Registers `diffuv correspond`.
void add_correspond_command(CLI::App& app);

/// Registers `diffuv segment`.
void add_segment_command(CLI::App& app);

/// Registers `diffuv bake` (in the param unity group: it runs param's pipeline).
void add_bake_command(CLI::App& app);

/// Registers `diffuv measure`.
void add_measure_command(CLI::App& app);

/// Registers `diffuv serve` (the painter: a local web server and its page).
void add_serve_command(CLI::App& app);

} // namespace diffuv_cli

#endif
