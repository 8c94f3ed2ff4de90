#include "pixel_common.h"

#include <algorithm>
#include <cstdio>
#include <cctype>

#include <fmt/core.h>

#include "cli.h"
#include "history/history_report.h"
#include "io/image.h"
#include "output_paths.h"

namespace zb::app {

using namespace cli;

void add_at_json_options(CLI::App* cmd, std::string& at, std::string& json) {
  cmd->add_option("--at", at, "Pixel X,Y (column, row from the top-left); several: X,Y;X,Y")
      ->required();
  cmd->add_option("--json", json, "The histories as JSON to this file (- : to stdout, instead of the text)");
}

namespace {

// "X,Y" with spaces around either number: whole numbers of at most 6 digits.
bool parse_pair(const std::string& text, int& x, int& y) {
  size_t i = 0;
  auto spaces = [&] { while (i < text.size() && text[i] == ' ') ++i; };
  auto number = [&](int& v) {
    const size_t from = i;
    v = 0;
    while (i < text.size() && i - from < 7 && std::isdigit(static_cast<unsigned char>(text[i])))
      v = v * 10 + (text[i++] - '0');
    return i > from && i - from <= 6;
  };
  spaces();
  if (!number(x)) return false;
  spaces();
  if (i >= text.size() || text[i++] != ',') return false;
  spaces();
  if (!number(y)) return false;
  spaces();
  return i == text.size();
}

}  // namespace

std::vector<std::pair<int, int>> parse_at(const std::string& text, int width, int height) {
  if (text.empty()) throw UsageError("--at: give the pixel as X,Y (several: X,Y;X,Y)");
  std::vector<std::pair<int, int>> out;
  size_t start = 0;
  while (start <= text.size()) {
    const size_t end = std::min(text.find(';', start), text.size());
    const std::string part = text.substr(start, end - start);
    int x = 0, y = 0;
    if (!parse_pair(part, x, y))
      throw UsageError(fmt::format("--at: '{}' is not X,Y (two whole numbers, pixel column and "
                                   "row from the top-left)", part));
    if (x >= width || y >= height)
      throw UsageError(fmt::format("--at: pixel ({}, {}) is outside the {}x{} frame (columns 0 to "
                                   "{}, rows 0 to {})", x, y, width, height, width - 1, height - 1));
    for (const auto& p : out)
      if (p == std::make_pair(x, y)) throw UsageError(fmt::format("--at: pixel ({}, {}) given twice", x, y));
    out.emplace_back(x, y);
    if (out.size() > kMaxPixels)
      throw UsageError(fmt::format("--at: more than {} pixels; render the frame instead", kMaxPixels));
    start = end + 1;
  }
  return out;
}

void check_json(const std::string& json) {
  if (!json.empty() && json != "-") check_writable("--json", json, ".json");
}

void write_histories(const FrameHistory& f, const std::string& title, const std::string& source,
                     const std::string& method, const std::string& json, const Scene* scene) {
  if (json == "-") {
    std::fputs(history_json(f, source, method, scene).c_str(), stdout);
    return;
  }
  // The file first: a write that fails stops before the text, naming the option.
  if (!json.empty())
    if (const std::string e = write_file_atomic(json, history_json(f, source, method, scene)); !e.empty())
      throw UsageError("--json: " + e);
  std::string text = title + "\n";
  for (const PixelHistory& h : f.pixels) text += "\n" + history_text(f, h, scene);
  std::fputs(text.c_str(), stdout);
}

}  // namespace zb::app
