// A command-line program's frame: run_main and the one-line parse errors; see cli.h.
#include "cli.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <exception>
#include <limits>

#include <fmt/core.h>

namespace zb::cli {

std::string count_text(size_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

std::string join(const std::vector<std::string>& items, const char* sep) {
  std::string out;
  for (const std::string& s : items) out += (out.empty() ? "" : sep) + s;
  return out;
}

std::string shell_word(const std::string& text) {
  if (!text.empty() && text.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                              "0123456789_-+=./,:@%") == std::string::npos)
    return text;
  std::string q = "'";
  for (const char c : text) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

namespace {

// Optimal string alignment distance: edits, with a swap of neighbours as one.
size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::vector<size_t>> d(a.size() + 1, std::vector<size_t>(b.size() + 1));
  for (size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (size_t i = 1; i <= a.size(); ++i)
    for (size_t j = 1; j <= b.size(); ++j) {
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1,
                          d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

// The name in `names` closest to `typed`, or "" when none is close: at most a third of the
// letters (`letters` of them) wrong, and never all of them.
std::string closest(const std::string& typed, const std::vector<std::string>& names, size_t letters) {
  std::string best;
  size_t best_distance = std::numeric_limits<size_t>::max();
  for (const std::string& n : names) {
    const size_t d = edit_distance(typed, n);
    if (d < best_distance) {
      best_distance = d;
      best = n;
    }
  }
  const bool close = best_distance <= std::max<size_t>(1, letters / 3) && best_distance < letters;
  return close ? best : "";
}

// The option of `cmd` closest to `typed` (closest).
std::string closest_option(const CLI::App& cmd, const std::string& typed) {
  std::vector<std::string> names;
  for (const CLI::Option* opt : cmd.get_options()) {
    for (const std::string& l : opt->get_lnames()) names.push_back("--" + l);
    for (const std::string& s : opt->get_snames()) names.push_back("-" + s);
  }
  return closest(typed, names, typed.size() - std::min(typed.find_first_not_of('-'), typed.size()));
}

// The commands `cmd` offers, in the order its help lists them.
std::vector<std::string> command_names(const CLI::App& cmd) {
  std::vector<std::string> names;
  for (const CLI::App* sub : cmd.get_subcommands([](const CLI::App*) { return true; }))
    names.push_back(sub->get_name());
  return names;
}

bool is_option(const std::string& arg) {
  return arg.size() > 1 && arg[0] == '-' && !std::isdigit(static_cast<unsigned char>(arg[1])) &&
         arg[1] != '.';
}

}  // namespace

std::string parse_error_line(const CLI::App& app, const CLI::ParseError& e) {
  const CLI::App* cmd = &app;
  std::string program = app.get_name();
  while (!cmd->get_subcommands().empty()) {
    cmd = cmd->get_subcommands().front();
    program += " " + cmd->get_name();
  }
  const std::vector<std::string> extras = app.remaining(true);
  // A command that needs one of its own and got none: the first word left is the one meant.
  if (cmd->get_require_subcommand_min() > 0 && cmd->get_subcommands().empty()) {
    const std::vector<std::string> names = command_names(*cmd);
    const auto word = std::find_if_not(extras.begin(), extras.end(), is_option);
    if (word == extras.end())
      return fmt::format("{}: error: a command is required: {} (see '{} --help')", program,
                         join(names), program);
    const std::string near = closest(*word, names, word->size());
    if (near.empty())
      return fmt::format("{}: error: unknown command '{}' (choose from {})", program, *word, join(names));
    return fmt::format("{}: error: unknown command '{}'; did you mean '{}'?", program, *word, near);
  }
  // An unknown option first: it may be a misspelt required one.
  const auto option = std::find_if(extras.begin(), extras.end(), is_option);
  const bool extra = e.get_exit_code() == static_cast<int>(CLI::ExitCodes::ExtrasError);
  if (option == extras.end() && extra && !extras.empty())
    return fmt::format("{}: error: unexpected argument '{}' (see '{} --help')", program,
                       extras.front(), program);
  if (option == extras.end())
    return fmt::format("{}: error: {} (see '{} --help')", app.get_name(), e.what(), program);
  const std::string typed = option->substr(0, option->find('='));
  const std::string near = closest_option(*cmd, typed);
  if (near.empty())
    return fmt::format("{}: error: unknown option '{}' (see '{} --help')", program, typed, program);
  return fmt::format("{}: error: unknown option '{}'; did you mean '{}'?", program, typed, near);
}

namespace {
std::string g_invoked_as;  // run_main's argv[0]
}  // namespace

std::string command_of(const CLI::App& cmd) {
  std::string words;
  const CLI::App* a = &cmd;
  for (; a->get_parent(); a = a->get_parent()) words = " " + a->get_name() + words;
  return shell_word(g_invoked_as.empty() ? a->get_name() : g_invoked_as) + words;
}

int run_main(CLI::App& app, int argc, const char* const* argv, const std::function<int()>& run) {
  const std::string name = app.get_name();
  g_invoked_as = argc > 0 && argv[0] ? argv[0] : "";
  try {
    app.parse(argc, argv);
    return run ? run() : 0;
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help
    std::fprintf(stderr, "%s\n", parse_error_line(app, e).c_str());
    return 2;
  } catch (const UsageError& e) {
    std::fprintf(stderr, "%s: error: %s\n", name.c_str(), e.what());
    return 2;
  } catch (const VerificationError& e) {
    std::fprintf(stderr, "%s: FAILED: %s\n", name.c_str(), e.what());
    return 1;
  } catch (const CannotRun& e) {
    std::fprintf(stderr, "%s: cannot run: %s\n", name.c_str(), e.what());
    return 3;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: internal error: %s\n", name.c_str(), e.what());
    return 1;
  }
}

}  // namespace zb::cli
