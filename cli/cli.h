// A command-line program's frame: parsing, the errors it reports and its exit codes. Every
// program's main() is run_main (docs/cli.md "Errors").
#pragma once

#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace zb::cli {

// Bad input from the user: "PROGRAM: error: WHAT", exit code 2, before any work.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A check failed (the RTL and the golden model disagreed, a suite's vectors do not match):
// "PROGRAM: FAILED: WHAT", exit code 1, after the report.
struct VerificationError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The machine lacks what the program needs (zblend_oracle: OpenGL on llvmpipe):
// "PROGRAM: cannot run: WHAT", exit code 3.
struct CannotRun : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Parses the command line into `app` and runs the program: `run`, after parsing, returns the
// exit code (a program whose subcommands run from their callbacks gives none: 0). Owns the
// error handling, one line on stderr each:
//   --help: the help, 0;
//   a parse error: parse_error_line, 2;
//   UsageError 2, VerificationError 1, CannotRun 3 (above);
//   any other exception, a fault of the program's own: "PROGRAM: internal error: WHAT", 1.
int run_main(CLI::App& app, int argc, const char* const* argv,
             const std::function<int()>& run = {});

// The one line for a CLI11 parse error of `app` (the top level). An unknown option names the
// closest valid one: "zblend render: error: unknown option '--scnee'; did you mean '--scene'?".
std::string parse_error_line(const CLI::App& app, const CLI::ParseError& e);

// `text` as one shell word: as it is when it needs no quoting, else in single quotes (for the
// commands a program prints for its user to run).
std::string shell_word(const std::string& text);

// The command line that runs `cmd`, a subcommand, as the user ran the program (run_main's
// argv[0]): "build/zblend conformance check". For the commands a program prints.
std::string command_of(const CLI::App& cmd);

// "1 pass", "14 passes": `n` and the word that goes with it.
std::string count_text(size_t n, const char* one, const char* many);

// "a, b, c", for error messages that name the valid choices.
std::string join(const std::vector<std::string>& items, const char* sep = ", ");

}  // namespace zb::cli
