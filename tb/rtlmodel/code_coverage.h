// RTL line and toggle coverage summed over every Verilated model of a run. Each RtlRop owns its
// VerilatedContext and a context's coverage points live only as long as its model, so in the
// coverage build (ZBLEND_RTL_COVERAGE) each model writes its counts to the scratch file as it
// closes and they are added here; write() gives one file in verilator_coverage's format, each
// point's count summed over the models, as `verilator_coverage --write` merges.
#pragma once

#include <cstdint>
#include <map>
#include <string>

namespace zb {

class CoverageTotals {
 public:
  CoverageTotals() = default;
  explicit CoverageTotals(std::string scratch_path) : scratch_(std::move(scratch_path)) {}

  // Where a closing model writes its counts before add_file().
  const std::string& scratch_path() const { return scratch_; }
  // Adds the counts of one model's coverage file, then removes the file.
  void add_file(const std::string& path);
  // Writes the sums (whole file or none: through a temporary and a rename).
  void write(const std::string& path) const;

  size_t points() const { return counts_.size(); }
  uint64_t models() const { return models_; }

 private:
  std::string scratch_;
  std::map<std::string, uint64_t> counts_;  // key (quoted, as written) -> count
  uint64_t models_ = 0;
};

}  // namespace zb
