// The rule for every output path, in every program (docs/cli.md, "Output paths"). A file must
// end in its extension and not be a directory; a directory must not be a file; the nearest
// existing directory above either must be writable and no file may stand on the way to it.
// Each check throws UsageError naming the option.
#pragma once

#include <string>
#include <vector>

namespace zb::cli {

struct OutputPath {
  const char* option;     // "--out", named in the error
  std::string path;       // empty: not given, skipped
  const char* extension;  // ".png" ...; nullptr: the path is a directory
};

// Checks, changing nothing on disk.
void check_outputs(const std::vector<OutputPath>& outputs);
// check_outputs, then creates the missing directories (mkdir -p): once every other check passed.
void create_output_dirs(const std::vector<OutputPath>& outputs);
// check_outputs for one file.
void check_writable(const char* option, const std::string& path, const char* extension);
// Throws UsageError(error) unless `error` is empty (a writer's error text, image.h).
void write_or_fail(const std::string& error);

}  // namespace zb::cli
