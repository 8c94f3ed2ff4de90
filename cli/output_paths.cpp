// The output-path rule; see output_paths.h.
#include "output_paths.h"

#include <filesystem>
#include <system_error>
#include <unistd.h>

#include <fmt/core.h>

#include "cli.h"

namespace zb::cli {

namespace fs = std::filesystem;

namespace {

// The nearest existing directory at or above `dir` (empty: "."), which must be writable with no
// file on the way.
void check_dir_above(const char* option, fs::path dir) {
  if (dir.empty()) dir = ".";
  std::error_code ec;
  while (!fs::exists(dir, ec)) {
    const fs::path up = dir.parent_path();
    if (up == dir) break;
    dir = up.empty() ? fs::path(".") : up;
  }
  if (!fs::is_directory(dir, ec))
    throw UsageError(fmt::format("{}: {} is a file, not a directory", option, dir.string()));
  if (::access(dir.c_str(), W_OK) != 0)
    throw UsageError(fmt::format("{}: directory '{}' is not writable", option, dir.string()));
}

void check_output(const OutputPath& o) {
  if (o.path.empty()) return;
  const fs::path path(o.path);
  if (!o.extension) return check_dir_above(o.option, path);
  if (path.extension() != o.extension)
    throw UsageError(fmt::format("{}: '{}' must end in {}", o.option, o.path, o.extension));
  std::error_code ec;
  if (fs::is_directory(path, ec))
    throw UsageError(fmt::format("{}: {} is a directory, not a {} file", o.option, o.path,
                                 o.extension));
  check_dir_above(o.option, path.parent_path());
}

}  // namespace

void check_outputs(const std::vector<OutputPath>& outputs) {
  for (const OutputPath& o : outputs) check_output(o);
}

void create_output_dirs(const std::vector<OutputPath>& outputs) {
  check_outputs(outputs);
  for (const OutputPath& o : outputs) {
    const fs::path dir = o.extension ? fs::path(o.path).parent_path() : fs::path(o.path);
    std::error_code ec;
    if (!o.path.empty() && !dir.empty()) fs::create_directories(dir, ec);
    if (ec)
      throw UsageError(fmt::format("{}: cannot create directory '{}': {}", o.option, dir.string(),
                                   ec.message()));
  }
}

void check_writable(const char* option, const std::string& path, const char* extension) {
  check_output({option, path, extension});
}

void write_or_fail(const std::string& error) {
  if (!error.empty()) throw UsageError(error);
}

}  // namespace zb::cli
