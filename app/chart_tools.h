// The chart scripts the lab and the sweeps run (scripts/*_charts.py) and the python3 that runs
// them.
#pragma once

#include <string>
#include <vector>

namespace zb::app {

// Runs argv without a shell; true when it exits 0. `silent` sends its output to /dev/null.
bool run_program(const std::vector<std::string>& args, bool silent);

struct ChartTools {
  std::string python;  // a python3 that imports matplotlib
  std::string script;  // scripts/<name>
};

// scripts/`name` of the source tree above the build directory holding this executable, else of
// the current directory, and the first python3 with matplotlib: the one on PATH, else Debian's
// (python3-matplotlib installs for /usr/bin/python3; a python3 earlier on PATH may lack it).
// Throws UsageError naming what is missing and `--no-charts` as the way around it.
ChartTools find_chart_tools(const std::string& name);

}  // namespace zb::app
