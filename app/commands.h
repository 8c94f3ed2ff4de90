// The zblend subcommands. Each registers itself on the top-level CLI11 app; what every program
// shares (run_main, the errors, the option checks, the output paths) is cli/'s.
#pragma once

#include <CLI/CLI.hpp>

namespace zb::app {

void add_render_command(CLI::App& app);
void add_trace_command(CLI::App& app);
void add_info_commands(CLI::App& app);  // methods, scenes, plan
void add_lab_command(CLI::App& app);
void add_pixel_command(CLI::App& app);
void add_sweep_command(CLI::App& app);
void add_conformance_command(CLI::App& app);  // conformance export, conformance check
// `export` and `check` themselves, on `parent`: zblend's conformance, or zblend-conformance.
void add_conformance_commands(CLI::App& parent);
void add_reach_command(CLI::App& parent);  // conformance reach
void add_suite_pixel_command(CLI::App& parent);  // conformance pixel

}  // namespace zb::app
