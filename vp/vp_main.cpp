// zblend_vp: the example virtual platform (docs/systemc.md "zblend_vp"). A host, a memory and one
// ZbRopTlm per inside asked for, loosely timed; each method's frame (or a trace's) is written
// into memory as a command stream, run by the ROP, read back from the framebuffer in memory and
// compared bit for bit with the golden model's render of the same passes.
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <malloc.h>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/core.h>
#include <systemc>
#include <tlm_utils/tlm_quantumkeeper.h>

#include "cli.h"
#include "io/image.h"
#include "io/trace.h"
#include "output_paths.h"
#include "pipeline/passes.h"
#include "pipeline/render.h"
#include "rop/rop.h"
#include "scene_options.h"
#include "zb_rop_tlm.h"
#include "zb_vp_host.h"
#include "zb_vp_memory.h"

namespace {

using namespace zb;
using namespace zb::vp;
using zb::cli::UsageError;
using zb::cli::VerificationError;

struct Options {
  cli::FrameOptions frame;
  std::string methods = "three-pass";
  std::string trace;
  std::string inside = "golden";
  std::string programming = "stream";
  std::string quantum = "1000";
  double clock_mhz = 100;
  bool no_dmi = false, no_check = false, quiet = false;
  std::string out, out_dir;
};

struct Frame {
  std::string name;  // the method, or the trace's file name
  // A trace file's trace, or a method's plan over the scene (its trace made too for register
  // programming: the host then sends it pass by pass).
  const PassPlan* plan = nullptr;
  std::optional<Trace> trace;
  Framebuffer reference;  // the golden model's, by the plan executor or the trace's replay
};

std::vector<InsideKind> parse_insides(const std::string& text) {
  if (text == "both") return {InsideKind::kGolden, InsideKind::kRtl};
  InsideKind k;
  if (!parse_inside(text, k))
    throw UsageError(fmt::format("--inside: '{}' is not golden, rtl or both", text));
  return {k};
}

sc_core::sc_time parse_quantum(const std::string& text, sc_core::sc_time clock) {
  if (text == "frame") return sc_core::sc_time(1, sc_core::SC_SEC);  // longer than any frame
  size_t used = 0;
  unsigned long long cycles = 0;
  try {
    cycles = std::stoull(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || cycles < 1 || text[0] == '-')
    throw UsageError(fmt::format("--quantum: '{}' is not a count of cycles (1 or more) or 'frame'",
                                 text));
  return clock * double(cycles);
}

// The frames to run; `rs` keeps the scene's fragments the plans' frames are made from.
std::vector<Frame> make_frames(const Options& o, Programming programming,
                               std::optional<RasterizedScene>& rs) {
  std::vector<Frame> out;
  if (!o.trace.empty()) {
    Frame f;
    try {
      f.trace = read_trace(o.trace);
    } catch (const TraceError& e) {
      throw UsageError(fmt::format("--trace: {}", e.what()));
    }
    f.name = o.trace;
    if (!o.no_check) {
      GoldenRop golden;
      replay_trace(*f.trace, golden);
      f.reference = golden.framebuffer();
    }
    out.push_back(std::move(f));
    return out;
  }
  const std::vector<std::string> names = cli::parse_methods(o.methods);
  const Viewport vp = cli::check_viewport(o.frame.width, o.frame.height, o.frame.depth_bits);
  const Scene scene = cli::resolve_scene(o.frame.scene, o.frame.camera);
  cli::print_warnings("zblend_vp", scene);
  rs = rasterize_scene(scene, vp, /*exact_depth=*/false);  // no exact reference here
  for (const std::string& name : names) {
    const PassPlan* plan = find_plan(name);
    if (!plan) {
      if (o.methods == "all") continue;  // the exact reference: no passes to run
      throw UsageError(fmt::format("--method: '{}' has no pass plan", name));
    }
    Frame f;
    f.name = name;
    f.plan = plan;
    if (programming == Programming::kRegisters) f.trace = make_trace(*rs, *plan);
    if (!o.no_check) {
      GoldenRop golden;
      render(*rs, *plan, golden);
      f.reference = golden.framebuffer();
    }
    out.push_back(std::move(f));
  }
  return out;
}

// The first pixel where the frame read back differs from the reference, or "".
std::string first_difference(const HostJob& j, const Framebuffer& ref) {
  for (size_t i = 0; i < ref.color.size(); ++i) {
    const Rgba8 a = j.frame[i], b = ref.color[i];
    if (!(a == b) || j.depth[i] != ref.depth[i])
      return fmt::format("pixel ({}, {}): colour {},{},{},{} depth 0x{:x}; golden render {},{},{},{} "
                         "depth 0x{:x}",
                         i % size_t(ref.width), i / size_t(ref.width), a.r, a.g, a.b, a.a,
                         j.depth[i], b.r, b.g, b.b, b.a, ref.depth[i]);
  }
  return "";
}

int run(const Options& o) {
  const std::vector<InsideKind> insides = parse_insides(o.inside);
  Programming programming;
  if (o.programming == "stream") programming = Programming::kStream;
  else if (o.programming == "registers") programming = Programming::kRegisters;
  else throw UsageError(fmt::format("--programming: '{}' is not stream or registers", o.programming));
  if (!(o.clock_mhz > 0 && o.clock_mhz <= 10000))
    throw UsageError(fmt::format("--clock-mhz: {} is out of range (above 0, at most 10000)", o.clock_mhz));
  const sc_core::sc_time clock(1000.0 / o.clock_mhz, sc_core::SC_NS);
  const sc_core::sc_time quantum = parse_quantum(o.quantum, clock);
  std::vector<cli::OutputPath> outputs;
  if (!o.out.empty()) outputs.push_back({"--out", o.out, ".png"});
  cli::check_outputs(outputs);
  cli::create_output_dirs(outputs);
  if (!o.out_dir.empty()) std::filesystem::create_directories(o.out_dir);

  std::optional<RasterizedScene> rs;
  const std::vector<Frame> frames = make_frames(o, programming, rs);
  if (!o.out.empty() && frames.size() * insides.size() != 1)
    throw UsageError("--out: one frame only (one method, one inside); give --out-dir for more");
  std::vector<HostJob> jobs;
  for (const Frame& f : frames)
    for (size_t r = 0; r < insides.size(); ++r) {
      HostJob j;
      j.rop = int(r);
      if (f.trace) j.trace = &*f.trace;
      else j.scene = &*rs, j.plan = f.plan;
      j.programming = programming;
      jobs.push_back(std::move(j));
    }

  const HostLayout layout = layout_for(jobs);
  tlm_utils::tlm_quantumkeeper::set_global_quantum(quantum);
  MemoryOptions mo;
  mo.bytes = layout.bytes;
  mo.dmi = !o.no_dmi;
  ZbVpMemory memory("memory", mo);
  ZbVpHost host("host", int(insides.size()), jobs, layout);
  host.mem.bind(memory.socket);
  std::vector<std::unique_ptr<ZbRopTlm>> rops;
  std::vector<std::unique_ptr<sc_core::sc_signal<bool>>> irqs;
  for (size_t r = 0; r < insides.size(); ++r) {
    RopTlmOptions ro;
    ro.inside = insides[r];
    ro.clock = clock;
    ro.dmi = !o.no_dmi;
    rops.push_back(std::make_unique<ZbRopTlm>(fmt::format("rop_{}", to_string(insides[r])).c_str(), ro));
    irqs.push_back(std::make_unique<sc_core::sc_signal<bool>>(fmt::format("irq{}", r).c_str()));
    rops[r]->dma.bind(memory.socket);
    (*host.rop[r]).bind(rops[r]->regs);
    rops[r]->irq_o(*irqs[r]);
    (*host.irq[r])(*irqs[r]);
  }
  if (!o.quiet)
    fmt::print("zblend_vp: {} frame(s), inside {}, {} programming, quantum {}, {}, memory {} MiB\n",
               frames.size(), o.inside, o.programming, quantum.to_string(),
               o.no_dmi ? "no DMI" : "DMI", layout.bytes >> 20);
  const auto wall = std::chrono::steady_clock::now();
  sc_core::sc_start();
  const double wall_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - wall).count();

  if (!o.quiet)
    fmt::print("{:<16} {:<6} {:>6} {:>10} {:>12} {:>12} {:>9} {:>9} {:>9}  {}\n", "frame", "inside",
               "passes", "fragments", "sim_us", "rop_cycles", "dma_tx", "reg_tx", "wall_ms", "check");
  int failures = 0;
  for (size_t i = 0; i < jobs.size(); ++i) {
    const HostJob& j = jobs[i];
    const Frame& f = frames[i / insides.size()];
    const ZbRopTlm& rop = *rops[size_t(j.rop)];
    std::string check = o.no_check ? "not checked" : "match";
    if (!j.error.empty()) {
      check = "ROP error: " + j.error + ": " + rop.last_error();
    } else if (j.passes != j.sent_passes || j.fragments_in != j.sent_fragments) {
      check = fmt::format("COUNTERS: PASSES {} and FRAGMENTS_IN {}, the host sent {} and {}",
                          j.passes, j.fragments_in, j.sent_passes, j.sent_fragments);
    } else if (!o.no_check) {
      const std::string diff = first_difference(j, f.reference);
      if (!diff.empty()) check = "MISMATCH at " + diff;
    }
    if (check != "match" && check != "not checked") ++failures;
    if (!o.quiet || (check != "match" && check != "not checked"))
      fmt::print("{:<16} {:<6} {:>6} {:>10} {:>12.1f} {:>12} {:>9} {:>9} {:>9.1f}  {}\n", f.name,
                 to_string(insides[size_t(j.rop)]), j.passes, j.fragments_in,
                 (j.end - j.start).to_seconds() * 1e6, j.cycles, j.dma_transactions,
                 j.rop_transactions, j.wall_ms, check);
    if (!o.out.empty() || !o.out_dir.empty()) {
      // A frame that failed is written black.
      const std::vector<Rgba8> black(j.frame.empty() ? size_t(j.width()) * size_t(j.height()) : 0);
      const std::string path =
          !o.out.empty() ? o.out
                         : fmt::format("{}/vp-{}-{}.png", o.out_dir, f.name,
                                       to_string(insides[size_t(j.rop)]));
      cli::write_or_fail(
          write_png(path, j.width(), j.height(), (j.frame.empty() ? black : j.frame).data()));
    }
  }
  if (!o.quiet)
    fmt::print("simulated {}, wall {:.1f} ms, memory transactions {}\n",
               sc_core::sc_time_stamp().to_string(), wall_ms, memory.transactions());
  if (failures)
    throw VerificationError(fmt::format("{} of {} frame(s) failed", failures, jobs.size()));
  return 0;
}

}  // namespace

// SystemC prints its banner before sc_main unless told otherwise: main() is ours, then.
int main(int argc, char** argv) {
  setenv("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE", "1", 0);
  // A frame's stream, its parse and the trace are tens of MB each, allocated and freed once a
  // frame: kept by the heap for the next (not mapped afresh, page by page, each time).
  mallopt(M_MMAP_THRESHOLD, 1 << 30);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
  return sc_core::sc_elab_and_sim(argc, argv);
}

int sc_main(int argc, char* argv[]) {
  // The host ends the run with sc_stop(): not news.
  sc_core::sc_report_handler::set_actions("/OSCI/SystemC", sc_core::SC_INFO,
                                          sc_core::SC_DO_NOTHING);
  CLI::App app{"zblend_vp: the ROP as a TLM-2.0 block in an example virtual platform (host, memory, "
               "ROP; loosely timed). Renders each method's frame through it and compares the "
               "frame in memory with the golden model's render bit for bit.",
               "zblend_vp"};
  Options o;
  cli::add_frame_options(&app, o.frame);
  app.add_option("--method,-m", o.methods, "Methods, 'a,b' or 'all'")->capture_default_str();
  app.add_option("--trace", o.trace, "A trace file (.zbt) to run instead of a scene");
  app.add_option("--inside", o.inside, "golden (timed by the cost model), rtl (the Verilated "
                                       "zb_rop) or both")->capture_default_str();
  app.add_option("--programming", o.programming,
                 "stream (the trace in memory, RUN_STREAM) or registers (command by command)")
      ->capture_default_str();
  app.add_option("--quantum", o.quantum, "The global quantum in ROP clock cycles, or 'frame'")
      ->capture_default_str();
  app.add_option("--clock-mhz", o.clock_mhz, "The ROP's clock")->capture_default_str();
  app.add_flag("--no-dmi", o.no_dmi, "The memory grants no DMI: every access a b_transport");
  app.add_flag("--no-check", o.no_check, "Skip the golden render the frames are compared with");
  app.add_option("--out", o.out, "The frame as a PNG (one frame)");
  app.add_option("--out-dir", o.out_dir, "Each frame as DIR/vp-METHOD-INSIDE.png");
  app.add_flag("--quiet,-q", o.quiet, "Print only failures");
  app.get_option("--trace")->excludes(app.get_option("--method"));
  return zb::cli::run_main(app, argc, argv, [&] { return run(o); });
}
