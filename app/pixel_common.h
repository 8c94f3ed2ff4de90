// What zblend pixel and conformance pixel share: the --at list, the --json check, and the
// histories written as text and JSON (docs/history.md).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "history/pixel_history.h"
#include "scene/scene.h"

namespace zb::app {

constexpr size_t kMaxPixels = 4096;  // the histories are held whole; a frame's worth is a render

// Registers --at (required) and --json on `cmd`.
void add_at_json_options(CLI::App* cmd, std::string& at, std::string& json);
// "X,Y[;X,Y...]" inside a width x height frame; UsageError naming --at otherwise.
std::vector<std::pair<int, int>> parse_at(const std::string& text, int width, int height);
// --json: "", "-" (stdout) or a writable .json path.
void check_json(const std::string& json);
// The histories on stdout as text under `title` (or as JSON with json "-"), and as JSON to the
// file `json` when one is named.
void write_histories(const FrameHistory& f, const std::string& title, const std::string& source,
                     const std::string& method, const std::string& json, const Scene* scene);

}  // namespace zb::app
