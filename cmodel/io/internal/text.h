// Text helpers of the scene-file loaders (io/): messages that stay on one line, numbers read
// strictly, tokens and lines. Internal to the golden model.
#pragma once

#include <string>
#include <vector>

namespace zb::text {

// Control characters (from a file name, a JSON key, a token) shown as '?': one line, always.
std::string printable(std::string text);
// Throws SceneFileError "FILE: PLACE: WHAT", printable.
[[noreturn]] void fail(const std::string& file, const std::string& place, const std::string& what);
// Newlines and runs of blanks folded into "; " and " ": the message stays one line.
std::string one_line(const std::string& text);
std::string lower_extension(const std::string& path);
// A file the scene names, joined to the scene's directory.
std::string beside(const std::string& scene, const std::string& name);

// The whole token as a number; `finite` tells infinities and NaN apart from garbage.
bool parse_number(const std::string& tok, double& out);
bool parse_int(const std::string& tok, long& out);
std::vector<std::string> split_blanks(const std::string& line);
std::vector<std::string> split(const std::string& text, char sep);

// The blank-separated tokens of each line without its comment, numbered from 1. A line ends at
// "\n", "\r\n" or a lone "\r", as tinyobjloader ends them.
template <typename F>
void for_each_line(const std::string& text, F&& f) {
  int number = 0;
  for (size_t start = 0; start < text.size();) {
    size_t end = text.find_first_of("\r\n", start);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(start, end - start);
    start = end + (text.compare(end, 2, "\r\n") == 0 ? 2 : 1);
    ++number;
    if (const size_t hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    const std::vector<std::string> tok = split_blanks(line);
    if (!tok.empty()) f(number, tok);
  }
}

// Checks that fields [first, first + n) of `tok` are finite numbers, optionally in [0, 1].
void expect_numbers(const std::string& file, int line, const std::vector<std::string>& tok,
                    size_t first, size_t n, bool unit_range);

}  // namespace zb::text
