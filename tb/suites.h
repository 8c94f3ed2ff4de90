// The testbench's named suites: each runs the golden model and the RTL in lockstep (zb::Cosim)
// and compares every colour and depth bit after every pass. This is their framework
// (suites.cpp: the registry, one iteration on a fresh Cosim, the failure's reproduce command);
// each suite is a file of its own, suite_<name>.cpp. tb/main.cpp is the command line.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "cosim.h"
#include "stimulus.h"

namespace zb::tb {

// What a run asks of the suites (the command line's options).
struct Config {
  uint64_t seed = 1;
  int iterations = 0;        // 0: the suite's default
  uint64_t fragments = 0;    // 0: the suite's default scale
  bool verbose = false;
  // What every iteration's Cosim is made with (cosim_options): the RTL model's options
  // (back-pressure, the whole run's waveform, plusargs, assertions, the timing check, re-read
  // stores, coverage totals) and the comparison's (the mismatch waveform, lock-step).
  CosimOptions cosim;
  std::function<void(double)> progress;  // when set: the share of the suite done, 0 to 1
  // The program and the arguments that do not choose the suite, seed, iterations or output
  // files, shell-quoted: a failure's reproduce command starts with it.
  std::string command;
};

// What a suite did: its counts, whether it failed, and a line of its own.
struct Tally {
  uint64_t iterations = 0, fragments = 0, pixels = 0, mismatches = 0;
  uint64_t stream_cycles = 0, io_cycles = 0;
  bool failed = false;
  bool port_only = false;  // drives no fragment (port): its words compared are its pixels
  std::string note;
};

// The Cosim options of one iteration: c.cosim with back-pressure pattern `seed`.
CosimOptions cosim_options(const Config& c, uint64_t seed);

// The share of a suite's work done: `total` units, added as done, reported to c.progress.
class WorkCounter {
 public:
  WorkCounter(const Config& c, uint64_t total) : c_(c), total_(total > 0 ? total : 1) {}
  void add(uint64_t n = 1) {
    done_ += n;
    if (c_.progress) c_.progress(done_ >= total_ ? 1.0 : double(done_) / double(total_));
  }

 private:
  const Config& c_;
  uint64_t total_;
  uint64_t done_ = 0;
};

// Runs one iteration's body on a fresh Cosim; folds its counts into `t`. Returns false on a
// mismatch (the report is printed) so the suite stops.
bool run_iteration(const char* suite, const Config& c, uint64_t seed, Tally& t,
                   const std::function<void(Cosim&)>& body);

// A failed iteration's last lines: the suite and seed, and the command that runs it again alone
// with the whole run's waveform.
void report_failure(const char* suite, const Config& c, uint64_t seed);

// One labelled pass: begin, draw `f`, end (compares).
void draw_pass(Cosim& cs, const std::string& name, const RopState& st,
               const std::vector<Fragment>& f);

// The suites, one function each, each in its own file, suite_<name>.cpp.
Tally suite_scenes(const Config& c);  // every built-in scene x every pass plan at 96x72
Tally suite_random(const Config& c);  // constrained-random states and streams
Tally suite_hazard(const Config& c);  // runs on 1-4 pixels; fragments per clock
Tally suite_window(const Config& c);  // directed issue-window streams
Tally suite_tiles(const Config& c);   // fast-clear bookkeeping across passes and tiles
Tally suite_clears(const Config& c);  // a store's write-back meeting the next clear
Tally suite_accum(const Config& c);   // accumulate mode at same-pixel distances 4..7
Tally suite_layers(const Config& c);  // layers mode (mlab-K) at same-pixel distances 4..7
Tally suite_blend(const Config& c);   // the blend unit, exhaustively, through the pipeline
Tally suite_states(const Config& c);  // every pass state of the coverage plan's cross
Tally suite_port(const Config& c);    // the tile port alone against a model of the planes

struct Suite {
  const char* name;
  const char* about;
  Tally (*run)(const Config&);
};

const std::vector<Suite>& suites();
const Suite* find_suite(const std::string& name);  // nullptr when unknown

}  // namespace zb::tb
