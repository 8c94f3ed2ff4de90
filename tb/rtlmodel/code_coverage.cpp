#include "code_coverage.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace zb {
namespace {

constexpr const char* kHeader = "# SystemC::Coverage-3";

}  // namespace

// A coverage file: the header, then one point a line, "C '<key>' <count>"; the key holds no
// newline and ends at the last "' ".
void CoverageTotals::add_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("coverage: cannot read " + path);
  std::string line;
  size_t line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    if (line.empty() || line[0] == '#') continue;
    const size_t end = line.rfind("' ");
    if (line.compare(0, 3, "C '") != 0 || end == std::string::npos || end < 2)
      throw std::runtime_error("coverage: " + path + ":" + std::to_string(line_no) +
                               ": not a coverage point");
    counts_[line.substr(2, end + 1 - 2)] += std::stoull(line.substr(end + 2));
  }
  ++models_;
  std::filesystem::remove(path);
}

void CoverageTotals::write(const std::string& path) const {
  const std::filesystem::path p(path);
  if (p.has_parent_path()) std::filesystem::create_directories(p.parent_path());
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp);
    out << kHeader << "\n";
    for (const auto& [key, count] : counts_) out << "C " << key << " " << count << "\n";
    if (!out.flush()) {
      std::remove(tmp.c_str());
      throw std::runtime_error("coverage: cannot write " + path);
    }
  }
  std::filesystem::rename(tmp, path);
}

}  // namespace zb
