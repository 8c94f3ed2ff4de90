// The zblend subcommands. Each registers itself on the top-level CLI11 app.
#pragma once

#include <stdexcept>
#include <string>

#include <CLI/CLI.hpp>

namespace zb::app {

// Bad input from the user: reported as one line, exit code 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

void add_render_command(CLI::App& app);
void add_info_commands(CLI::App& app);  // methods, scenes, plan

// "a, b, c", for error messages that name the valid choices.
std::string join(const std::vector<std::string>& items, const char* sep = ", ");

}  // namespace zb::app
