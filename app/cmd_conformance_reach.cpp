// zblend conformance reach: the suite's reach on the kit-reachable plan bins and the suite's
// goals, computed on the golden model for a DUT's tile (conformance/reach.h); the tiers' ranking.
#include <algorithm>
#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <sstream>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "cli.h"
#include "commands.h"
#include "io/image.h"
#include "output_paths.h"
#include "reach.h"
#include "suite.h"

namespace zb::app {

using namespace cli;

namespace {

namespace cf = zb::conformance;

struct ReachOptions {
  std::string tile = "64x64", json;
  int window = 8, gap = 0;
  uint32_t gap_seed = 1;
  bool quick = false, rank = false, holes = false;
  std::string schedule = "pass";
  uint64_t seed = 0;
};

cf::DutShape parse_shape(const ReachOptions& o) {
  cf::DutShape s;
  char x = 0;
  std::istringstream in(o.tile);
  if (!(in >> s.tile_w >> x >> s.tile_h) || x != 'x' || !in.eof() || s.tile_w < 1 ||
      s.tile_h < 1 || s.tile_w > 4096 || s.tile_h > 4096)
    throw UsageError(fmt::format("--tile: '{}' is not WxH (1 to 4096 each, e.g. 16x16)", o.tile));
  if (o.window < 1 || o.window > 64)
    throw UsageError(fmt::format("--window: {} is outside 1 to 64", o.window));
  s.window = o.window;
  if (o.gap < 0 || o.gap > 95) throw UsageError(fmt::format("--gap: {} is outside 0 to 95", o.gap));
  s.gap_pct = o.gap;
  s.seed = o.gap_seed;
  s.resident = o.schedule == "resident";
  return s;
}

// "pass_state[depth=less,...]" -> "pass_state"; "goal.tile_origin[...]" -> "goal.tile_origin".
std::string entry_of(const std::string& bin) {
  const size_t bracket = bin.find('[');
  return bin.substr(0, bracket != std::string::npos ? bracket : bin.rfind('.'));
}

void run_reach(const ReachOptions& o) {
  const cf::DutShape shape = parse_shape(o);
  if (!o.json.empty()) check_writable("--json", o.json, ".json");
  std::vector<cf::TestSpec> tests = o.seed ? cf::seeded_tests(o.seed) : cf::suite_tests(o.quick);
  const std::vector<cf::BinCounts> reach = cf::tests_reach(tests, shape);
  const cf::BinList list = cf::reach_bins(shape);
  std::set<std::string> hit;
  for (const cf::BinCounts& r : reach)
    for (const auto& [bin, n] : r) hit.insert(bin);

  // Per entry: bins, reached.
  std::vector<std::string> order;
  std::map<std::string, std::pair<size_t, size_t>> per;
  for (const auto* group : {&list.plan, &list.goals})
    for (const std::string& b : *group) {
      const std::string e = entry_of(b);
      if (!per.count(e)) order.push_back(e);
      auto& [all, got] = per[e];
      ++all;
      got += hit.count(b);
    }
  fmt::print("reach of {} tests at tile {}x{}, window {}, gap {} %\n", tests.size(), shape.tile_w,
             shape.tile_h, shape.window, shape.gap_pct);
  fmt::print("{:<28} {:>7} {:>8}\n", "entry", "bins", "reached");
  for (const std::string& e : order)
    fmt::print("{:<28} {:>7} {:>8}\n", e, per[e].first, per[e].second);
  auto total = [&](const std::vector<std::string>& bins) {
    return size_t(std::count_if(bins.begin(), bins.end(), [&](const std::string& b) { return hit.count(b); }));
  };
  const size_t plan_hit = total(list.plan), goal_hit = total(list.goals);
  fmt::print("plan bins a DUT reaches through the kit: {} of {} ({:.1f} %)\n", plan_hit,
             list.plan.size(), 100.0 * double(plan_hit) / double(list.plan.size()));
  fmt::print("suite goals: {} of {} ({:.1f} %)\n", goal_hit, list.goals.size(),
             100.0 * double(goal_hit) / double(list.goals.size()));
  if (o.holes)
    for (const auto* group : {&list.plan, &list.goals})
      for (const std::string& b : *group)
        if (!hit.count(b)) fmt::print("hole {}\n", b);

  if (o.rank) {
    std::vector<std::string> all = list.plan;
    all.insert(all.end(), list.goals.begin(), list.goals.end());
    size_t cum = 0;
    fmt::print("ranking (the test adding the most bins not yet hit, each step):\n");
    for (const auto& [i, fresh] : cf::rank_tests(reach, all)) {
      cum += fresh;
      fmt::print("  {:<30} +{:<6} {:>6}\n", tests[i].name, fresh, cum);
    }
  }
  if (!o.json.empty()) {
    nlohmann::json j = {{"tile_w", shape.tile_w}, {"tile_h", shape.tile_h}, {"gap", shape.gap_pct},
                        {"resident", shape.resident},
                        {"window", shape.window}, {"plan_bins", list.plan},
                        {"goal_bins", list.goals}};
    nlohmann::json& t = j["tests"] = nlohmann::json::object();
    for (size_t i = 0; i < tests.size(); ++i) t[tests[i].name] = reach[i];
    write_or_fail(write_file_atomic(o.json, j.dump(1) + "\n"));
  }
}

}  // namespace

void add_reach_command(CLI::App& parent) {
  auto o = std::make_shared<ReachOptions>();
  CLI::App* cmd = parent.add_subcommand(
      "reach", "The suite's reach on the golden model: the coverage plan's kit-reachable bins "
               "and the suite's goals, for a DUT's tile (docs/conformance.md \"What the suite "
               "reaches\")");
  cmd->add_option("--tile", o->tile, "The DUT's tile, WxH (the testbench bins fragments by it)")
      ->capture_default_str();
  cmd->add_option("--window", o->window, "Same-pixel distances counted to WINDOW + 1 (the plan's)")
      ->capture_default_str();
  cmd->add_option("--gap", o->gap,
                  "The testbench's --gap (percent of fragment offers preceded by a gap), "
                  "modelled draw for draw under tight timing")
      ->capture_default_str();
  cmd->add_option("--gap-seed", o->gap_seed, "The testbench's --seed for the gaps")
      ->capture_default_str();
  cmd->add_option("--schedule", o->schedule, "The testbench's schedule: pass, or resident (tiles)")
      ->check(CLI::IsMember({"pass", "resident"}))
      ->capture_default_str();
  cmd->add_flag("--quick", o->quick, "The quick tier only");
  cmd->add_option("--seed", o->seed, "The seeded random tier of this seed instead");
  cmd->add_flag("--rank", o->rank, "Print the greedy ranking (the quick tier's choice)");
  cmd->add_flag("--holes", o->holes, "List every bin left unhit");
  cmd->add_option("--json", o->json, "Write each test's bins and counts here");
  cmd->callback([o] { run_reach(*o); });
}

}  // namespace zb::app
