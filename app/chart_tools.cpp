#include "chart_tools.h"

#include <fcntl.h>
#include <filesystem>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/core.h>

#include "cli.h"

extern char** environ;

namespace zb::app {

using namespace cli;  // the programs' shared options, checks and errors (cli/)

namespace fs = std::filesystem;

bool run_program(const std::vector<std::string>& args, bool silent) {
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (silent) {
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  }
  pid_t pid = 0;
  const int err = posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (err != 0) return false;
  int status = 0;
  if (waitpid(pid, &status, 0) != pid) return false;
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

ChartTools find_chart_tools(const std::string& name) {
  ChartTools t;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  const fs::path beside = ec ? fs::path() : exe.parent_path().parent_path();
  for (const fs::path& base : {beside, fs::current_path(ec)}) {
    const fs::path p = base / "scripts" / name;
    if (t.script.empty() && !base.empty() && fs::is_regular_file(p, ec)) t.script = p.string();
  }
  if (t.script.empty())
    throw UsageError(fmt::format("--no-charts: scripts/{} not found beside the build directory "
                                 "or in the current directory; run from the source tree or pass "
                                 "--no-charts", name));
  for (const char* p : {"python3", "/usr/bin/python3"}) {
    if (run_program({p, "-c", "import matplotlib"}, true)) {
      t.python = p;
      break;
    }
  }
  if (t.python.empty())
    throw UsageError("--no-charts: no python3 with matplotlib (apt-get install "
                     "python3-matplotlib, or scripts/setup.sh); or pass --no-charts");
  return t;
}

}  // namespace zb::app
