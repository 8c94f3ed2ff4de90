#include "waves.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <stdexcept>

#include <gtkwave/fstapi.h>

#include "tile_io.h"

namespace zb {

namespace {

// zb_rop's stage instances in pipeline order (docs/rtl.md), with the stages they span.
struct Stage {
  const char* instance;
  const char* stages;
};
constexpr Stage kStages[] = {
    {"u_input", "I/S: zb_input"},         {"u_window", "W: zb_issue_window"},
    {"u_depth", "X1..X4: zb_depth"},
    {"u_depth.g_renamed", "the depth banks, role_q: bank 1 is depth (zb_depth, renamed copies)"},
    {"u_operands", "X1..X6: zb_operands"},
    {"u_weight", "M..X8: zb_weight"},      {"u_color", "X5..X11: zb_color"},
    {"u_accum", "X5..X11: zb_accum"},      {"u_counters", "counters: zb_counters"},
    {"u_tile_counters", "tile port counters: zb_counters"},
    {"g_resolve", "tile port: a store's resolves, under the background or of the accumulation"},
};

struct Var {
  std::string name;  // as GTKWave names it: scope.name[msb:lsb]
  uint32_t bits = 1;
};

// The FST's scopes by path ("tb", "zb_rop", "zb_rop.zb_rop.u_input", ...) and their own
// variables, in file order.
struct Hierarchy {
  std::set<std::string> scopes;
  std::map<std::string, std::vector<Var>> vars;
};

Hierarchy read_hierarchy(const std::string& fst) {
  void* r = fstReaderOpen(fst.c_str());
  if (!r) throw std::runtime_error("save file: cannot read the FST " + fst);
  Hierarchy h;
  std::vector<std::string> path;
  auto joined = [&] {
    std::string s;
    for (const std::string& p : path) s += (s.empty() ? "" : ".") + p;
    return s;
  };
  while (const fstHier* e = fstReaderIterateHier(r)) {
    if (e->htyp == FST_HT_SCOPE) {
      path.emplace_back(e->u.scope.name);
      h.scopes.insert(joined());
    } else if (e->htyp == FST_HT_UPSCOPE) {
      if (!path.empty()) path.pop_back();
    } else if (e->htyp == FST_HT_VAR && e->u.var.typ != FST_VT_VCD_PARAMETER) {
      // (parameters are constants, and GTKWave shows none from a save file)
      std::string n(e->u.var.name);
      n.erase(std::remove(n.begin(), n.end(), ' '), n.end());  // "x [3:0]" -> "x[3:0]"
      h.vars[joined()].push_back({joined() + "." + n, e->u.var.length});
    }
  }
  fstReaderClose(r);
  return h;
}

// GTKWave's zoom z for `span` ps across the wave pane: it draws 2^-z time units per 200
// pixels. The pane of a 1600-pixel window beside the tree and the names is about 850 wide.
double zoom_for(uint64_t span_ps) {
  constexpr double kPanePixels = 850, kFramePixels = 200;
  return -std::log2(std::max(1.0, double(span_ps) * kFramePixels / kPanePixels));
}

// A group of traces: its opening comment, each trace with its format flags (binary for a bit,
// signed decimal for the testbench's numbers, so "none" reads -1; hex else), its closing comment.
void group(std::ofstream& o, const std::string& title, const std::vector<Var>& vars) {
  if (vars.empty()) return;
  o << "@800200\n-" << title << "\n";
  for (const Var& v : vars) {
    const bool number = v.name.rfind("tb.", 0) == 0 && (v.name.find("index") != std::string::npos ||
                                                      v.name.find("prim") != std::string::npos ||
                                                      v.name.find("pass_no") != std::string::npos);
    o << (v.bits == 1 ? "@28\n" : number ? "@424\n" : "@22\n") << v.name << "\n";
  }
  o << "@1000200\n-" << title << "\n";
}

}  // namespace

void WaveProbe::retire(const Retire& r, const PixelWrites* g) {
  if (r.kind != Retire::Kind::kRetired) return;
  if (r.stage == RetireStage::kX4) {
    x4_retire = true;
    x4_index = r.fragment;
    x4_dwe = g && g->depth;
    x4_depth = g ? g->z : 0;
    x4_vwe = g && g->coverage;
    x4_cov = g ? g->cov : 0;
  } else {
    x11_retire = true;
    x11_index = r.fragment;
    x11_cwe = g && g->color;
    x11_color = g ? pack_rgba(g->rgba) : 0;
    x11_awe = g && g->accum;
    x11_acc = g ? g->acc : std::array<uint32_t, 4>{};
    x11_reveal = g ? g->reveal : 0;
    x11_lwe = g && g->layers;
    x11_layers = g ? g->lay : PixelLayers{};
  }
}

void WaveProbe::next_cycle() {
  x4_retire = x4_dwe = x4_vwe = x11_retire = x11_cwe = x11_awe = x11_lwe = mismatch = false;
  x4_index = x11_index = kNone;
  x4_depth = x4_cov = x11_color = x11_reveal = 0;
  x11_acc = {};
  x11_layers = {};
}

bool ProbeSink::retire(const Retire& r) {
  probe_.retire(r, next_ ? next_->expected(r.fragment) : nullptr);
  const bool ok = !next_ || next_->retire(r);
  probe_.mismatch = probe_.mismatch || !ok;
  return ok;
}

bool ProbeSink::store(const StoreBeat& b) {
  const bool ok = !next_ || next_->store(b);
  probe_.mismatch = probe_.mismatch || !ok;
  return ok;
}

std::string wave_rise_text(uint64_t cycle) {
  return std::to_string(wave_rise_ps(cycle) / 1000) + " ns";
}

std::string write_save_file(const std::string& fst, const WaveView& v, const std::string& gtkw) {
  const Hierarchy h = read_hierarchy(fst);
  const std::filesystem::path path =
      gtkw.empty() ? std::filesystem::path(fst).replace_extension(".gtkw") : std::filesystem::path(gtkw);
  std::ofstream o(path);
  if (!o) throw std::runtime_error("save file: cannot write " + path.string());
  const std::string abs_fst = std::filesystem::absolute(fst).string();
  o << "[*] zblend: " << (v.title.empty() ? "RTL waveform" : v.title) << "\n";
  o << "[*] 10 ns clock: cycle c's rising edge at c * 10 + 5 ns\n";
  o << "[dumpfile] \"" << abs_fst << "\"\n";
  o << "[savefile] \"" << std::filesystem::absolute(path).string() << "\"\n";
  // The view's cycles, clipped to the file's.
  void* r = fstReaderOpen(fst.c_str());
  uint64_t first = 0, last = 0;
  if (r) {
    first = fstReaderGetStartTime(r);
    last = fstReaderGetEndTime(r);
    fstReaderClose(r);
  }
  const uint64_t from = std::max(first, v.from == WaveView::kNone ? first : wave_fall_ps(v.from));
  const uint64_t to = v.to == WaveView::kNone ? last : std::min(last, wave_fall_ps(v.to + 1));
  o << "[timestart] " << from << "\n";
  o << "[size] 1600 900\n[pos] -1 -1\n";
  o << "*" << zoom_for(to > from ? to - from : kWaveClockPs) << " "
    << (v.markers.empty() ? std::string("-1") : std::to_string(wave_rise_ps(v.markers[0].cycle)));
  for (size_t i = 0; i < 26; ++i)
    o << " " << (i < v.markers.size() ? std::to_string(wave_rise_ps(v.markers[i].cycle)) : "-1");
  o << "\n";
  for (size_t i = 0; i < v.markers.size() && i < 26; ++i)
    o << "[markername] " << char('A' + i) << v.markers[i].name << "\n";
  o << "[sst_width] 260\n[signals_width] 330\n[sst_expanded] 1\n";
  // The testbench's probe, the ports, M (zb_rop's own signals), then the stages.
  auto at = [&](const std::string& scope) {
    auto it = h.vars.find(scope);
    return it == h.vars.end() ? std::vector<Var>{} : it->second;
  };
  group(o, "testbench: fragment, pass, golden writes, mismatch", at("tb"));
  const std::vector<Var> ports = at("zb_rop");
  group(o, "zb_rop ports", ports);
  std::set<std::string> port_names;
  for (const Var& p : ports) port_names.insert(p.name.substr(p.name.find('.') + 1));
  std::vector<Var> own;
  for (const Var& x : at("zb_rop.zb_rop"))
    if (!port_names.count(x.name.substr(x.name.find('.', x.name.find('.') + 1) + 1)))
      own.push_back(x);
  group(o, "M: pass state, issue, reads (zb_rop)", own);
  for (const Stage& s : kStages) {
    const std::string scope = std::string("zb_rop.zb_rop.") + s.instance;
    if (!h.scopes.count(scope)) continue;  // not in this netlist (the mutants' is flat)
    group(o, std::string(s.stages) + " (" + s.instance + ")", at(scope));
  }
  if (!o) throw std::runtime_error("save file: cannot write " + path.string());
  return path.string();
}

}  // namespace zb
