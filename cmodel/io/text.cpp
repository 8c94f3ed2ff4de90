#include "io/internal/text.h"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include <fmt/core.h>

#include "io/scene_file.h"

namespace zb::text {

namespace fs = std::filesystem;
// Control characters (from a file name, a JSON key, a token) shown as '?': one line, always.
std::string printable(std::string text) {
  for (char& c : text)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
  return text;
}

[[noreturn]] void fail(const std::string& file, const std::string& place, const std::string& what) {
  throw SceneFileError(printable(fmt::format("{}: {}: {}", file, place, what)));
}

// Newlines and runs of blanks folded into "; " and " ": the message stays one line.
std::string one_line(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '\n' || c == '\r') {
      if (!out.empty() && out.back() != ' ') out += "; ";
    } else {
      out += c;
    }
  }
  while (!out.empty() && (out.back() == ' ' || out.back() == ';')) out.pop_back();
  return out.empty() ? "unknown error" : out;
}

std::string lower_extension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

// A file the scene names, joined to the scene's directory.
std::string beside(const std::string& scene, const std::string& name) {
  return (fs::path(scene).parent_path() / name).string();
}

// ---- numbers ---------------------------------------------------------------------------------

// The whole token as a number; `finite` tells infinities and NaN apart from garbage.
bool parse_number(const std::string& tok, double& out) {
  if (tok.empty()) return false;
  char* end = nullptr;
  out = std::strtod(tok.c_str(), &end);
  return end == tok.c_str() + tok.size();
}

bool parse_int(const std::string& tok, long& out) {
  if (tok.empty()) return false;
  char* end = nullptr;
  errno = 0;
  out = std::strtol(tok.c_str(), &end, 10);
  return errno == 0 && end == tok.c_str() + tok.size();
}

std::vector<std::string> split_blanks(const std::string& line) {
  std::vector<std::string> out;
  std::istringstream in(line);
  std::string tok;
  while (in >> tok) out.push_back(tok);
  return out;
}

std::vector<std::string> split(const std::string& text, char sep) {
  std::vector<std::string> out;
  size_t start = 0;
  while (true) {
    const size_t at = text.find(sep, start);
    out.push_back(text.substr(start, at == std::string::npos ? std::string::npos : at - start));
    if (at == std::string::npos) return out;
    start = at + 1;
  }
}

// Checks that fields [first, first + n) of `tok` are finite numbers, optionally in [0, 1].
void expect_numbers(const std::string& file, int line, const std::vector<std::string>& tok,
                    size_t first, size_t n, bool unit_range) {
  const std::string place = fmt::format("line {}", line);
  if (tok.size() < first + n)
    fail(file, place, fmt::format("'{}' needs {} number{}, has {}", tok[0], n, n > 1 ? "s" : "",
                                  tok.size() - first));
  for (size_t i = first; i < first + n; ++i) {
    double v = 0;
    if (!parse_number(tok[i], v)) fail(file, place, fmt::format("'{}': '{}' is not a number", tok[0], tok[i]));
    if (!std::isfinite(static_cast<float>(v)))  // read as float: 1e39 is infinite too
      fail(file, place, fmt::format("'{}': {} is not finite", tok[0], tok[i]));
    if (unit_range && (v < 0 || v > 1))
      fail(file, place, fmt::format("'{}': {} is outside 0 to 1", tok[0], tok[i]));
  }
}

}  // namespace zb::text
