// zblend_test_rop_tlm: ZbRopTlm over its sockets, as a platform's software sees it. A tester
// thread runs named checks in order (register map, base protocol, debug transport, a frame by
// registers, command errors, DMI); each prints "ok NAME" or "FAIL NAME: what". Exit 1 on a FAIL.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <fmt/core.h>
#include <systemc>
#include <tlm>
#include <tlm_utils/simple_initiator_socket.h>

#include "io/trace.h"
#include "rop/fragment.h"
#include "zb_rop_regs.h"
#include "zb_rop_tlm.h"
#include "zb_vp_memory.h"

namespace {

using namespace zb;
using namespace zb::vp;
using sc_core::SC_NS;
using sc_core::SC_US;
using tlm::tlm_response_status;
constexpr tlm::tlm_command kRd = tlm::TLM_READ_COMMAND, kWr = tlm::TLM_WRITE_COMMAND;

struct Failed { std::string what; };
void expect(bool ok, const std::string& what) {
  if (!ok) throw Failed{what};
}
void expect_eq(uint64_t got, uint64_t want, const std::string& what) {
  if (got != want) throw Failed{fmt::format("{}: 0x{:x}, expected 0x{:x}", what, got, want)};
}
std::string name_of(tlm_response_status s) {
  tlm::tlm_generic_payload p;
  p.set_response_status(s);
  return p.get_response_string();
}
void expect_resp(tlm_response_status got, tlm_response_status want, const std::string& what) {
  if (got != want) throw Failed{fmt::format("{}: {}, not {}", what, name_of(got), name_of(want))};
}

// Memory: small, so that a DMA past its end is cheap to provoke.
constexpr uint64_t kMemBytes = 1u << 20;
constexpr uint64_t kFragAt = 0x1000, kFbAt = 0x10000, kDepthAt = 0x20000, kStreamAt = 0x40000;
constexpr int kW = 32, kH = 32;
constexpr uint32_t kFbStride = kW * 4 + 16;  // padding after each row: stores must skip it
constexpr uint8_t kSentinel = 0xee;
constexpr Rgba8 kClear{0x10, 0x20, 0x40, 0x80};
constexpr uint32_t kFar = (1u << kDefaultDepthBits) - 1;

uint32_t word_of(Rgba8 c) {
  return c.r | uint32_t(c.g) << 8 | uint32_t(c.b) << 16 | uint32_t(c.a) << 24;
}
uint32_t code_of(ErrorCode c) { return status::kError | uint32_t(c) << status::kCodeShift; }

bool is_hole(uint64_t a) { return a == 0x3c || a == 0x74; }
// The RW registers: FRAME_SIZE to STREAM_BYTES but the hole and TILE_SIZE (zb_rop_regs.h).
std::vector<uint64_t> rw_registers() {
  std::vector<uint64_t> out;
  for (uint64_t a = reg::kFrameSize; a <= reg::kStreamBytes; a += 4)
    if (!is_hole(a) && a != reg::kTileSize) out.push_back(a);
  return out;
}
const uint64_t kPairs[] = {reg::kFragAddrLo, reg::kFbAddrLo, reg::kDepthAddrLo, reg::kStreamAddrLo};

class Tester : public sc_core::sc_module {
 public:
  tlm_utils::simple_initiator_socket<Tester> bus;
  sc_core::sc_in<bool> irq;
  int passed = 0, failed = 0;

  Tester(sc_core::sc_module_name name, ZbRopTlm& rop, ZbVpMemory& mem)
      : sc_module(name), bus("bus"), irq("irq"), rop_(rop), mem_(mem) {
    SC_HAS_PROCESS(Tester);
    SC_THREAD(run);
  }

 private:
  ZbRopTlm& rop_;
  ZbVpMemory& mem_;

  void check(const char* name, const std::function<void()>& body) {
    std::string what;
    try {
      body();
    } catch (const Failed& f) {
      what = f.what;
    } catch (const std::exception& e) {  // the model threw past its own error reporting
      what = fmt::format("exception: {}", e.what());
    }
    ++(what.empty() ? passed : failed);
    std::printf("%s %s%s%s\n", what.empty() ? "ok" : "FAIL", name, what.empty() ? "" : ": ",
                what.c_str());
    std::fflush(stdout);
  }

  // ---- Bus access -------------------------------------------------------------------------------
  static void fill(tlm::tlm_generic_payload& tx, tlm::tlm_command cmd, uint64_t a, void* data,
                   unsigned len) {
    tx.set_command(cmd);
    tx.set_address(a);
    tx.set_data_ptr(static_cast<uint8_t*>(data));
    tx.set_data_length(len);
    tx.set_streaming_width(len);
    tx.set_byte_enable_ptr(nullptr);
    tx.set_dmi_allowed(false);
    tx.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
  }
  // One b_transport, which must leave a response. `sync` false: the tester's time stays (its
  // next access lands before the ROP's thread can run).
  tlm_response_status transport(tlm::tlm_generic_payload& tx, bool sync = true) {
    sc_core::sc_time delay = sc_core::SC_ZERO_TIME;
    bus->b_transport(tx, delay);
    const uint64_t a = tx.get_address();
    expect(tx.get_response_status() != tlm::TLM_INCOMPLETE_RESPONSE,
           fmt::format("0x{:x}: response left incomplete", a));
    expect(!tx.is_dmi_allowed(), fmt::format("0x{:x}: a register access offers DMI", a));
    if (sync) wait(delay);
    return tx.get_response_status();
  }
  tlm_response_status access(tlm::tlm_command cmd, uint64_t a, uint32_t& v, bool sync = true) {
    tlm::tlm_generic_payload tx;
    fill(tx, cmd, a, &v, 4);
    return transport(tx, sync);
  }
  uint32_t rd(uint64_t a) {
    uint32_t v = 0;
    expect_resp(access(kRd, a, v), tlm::TLM_OK_RESPONSE, fmt::format("read 0x{:x}", a));
    return v;
  }
  uint64_t rd64(uint64_t lo) { return rd(lo) | uint64_t(rd(lo + 4)) << 32; }
  void wr(uint64_t a, uint32_t v, bool sync = true) {
    expect_resp(access(kWr, a, v, sync), tlm::TLM_OK_RESPONSE, fmt::format("write 0x{:x}", a));
  }
  void wr64(uint64_t lo, uint64_t v) {
    wr(lo, uint32_t(v));
    wr(lo + 4, uint32_t(v >> 32));
  }
  unsigned dbg(tlm::tlm_command cmd, uint64_t a, void* data, unsigned len) {
    tlm::tlm_generic_payload tx;
    fill(tx, cmd, a, data, len);
    return bus->transport_dbg(tx);
  }

  // ---- Commands ---------------------------------------------------------------------------------
  // STATUS polled until not busy; the irq line read once its deltas have settled.
  uint32_t wait_idle(const std::string& what) {
    uint32_t s = rd(reg::kStatus);
    for (int i = 0; (s & status::kBusy) && i < 200000; ++i) {
      wait(1, SC_US);
      s = rd(reg::kStatus);
    }
    expect(!(s & status::kBusy), fmt::format("{}: still busy after 200 ms", what));
    wait(1, SC_NS);
    expect(irq.read(), fmt::format("{}: STATUS 0x{:x} but irq low", what, s));
    return s;
  }
  void clear_status() {
    wr(reg::kStatus, status::kDone | status::kError);
    wait(1, SC_NS);
    // The code [15:8] may stay until the next command: only busy, done and error are cleared.
    expect_eq(rd(reg::kStatus) & 0xff, 0, "STATUS [7:0] after writing done and error back");
    expect(!irq.read(), "irq high after STATUS written back");
  }
  // A command run to its end: done, or the error `e`; STATUS written back after it.
  void exec(uint32_t c, const std::string& what, ErrorCode e = ErrorCode::kNone) {
    wr(reg::kCommand, c);
    const uint32_t s = wait_idle(what), want = e == ErrorCode::kNone ? status::kDone : code_of(e);
    clear_status();
    if (s != want)
      throw Failed{fmt::format("{}: STATUS 0x{:x}, expected 0x{:x} (last error: '{}')", what, s,
                               want, rop_.last_error())};
  }
  void exec(Command c, const std::string& what, ErrorCode e = ErrorCode::kNone) {
    exec(uint32_t(c), what, e);
  }

  // The set-up registers: a 32x32 frame in the trace defaults, colour and depth planes in memory.
  void setup() {
    const WboitFormat wb;
    wr(reg::kFrameSize, kW | kH << 16);
    wr(reg::kFrameFormat, kDefaultDepthBits | kDefaultCoverageSamples << 8);
    wr(reg::kWboit, wb.acc_bits | wb.rev_bits << 8 | wb.weight_bits << 16);
    wr(reg::kClearColor, word_of(kClear));
    wr64(reg::kFbAddrLo, kFbAt);
    wr(reg::kFbStride, kFbStride);
    wr64(reg::kDepthAddrLo, kDepthAt);
    wr(reg::kDepthStride, kW * 4);
  }
  // Fragment records into memory by the backdoor; FRAG_ADDR and FRAG_COUNT at them.
  void put_fragments(const std::vector<Fragment>& fs) {
    std::string bytes;
    for (const Fragment& f : fs) encode_fragment(bytes, f);
    std::memcpy(mem_.data() + kFragAt, bytes.data(), bytes.size());
    wr64(reg::kFragAddrLo, kFragAt);
    wr(reg::kFragCount, uint32_t(fs.size()));
  }
  void wipe_planes() {
    std::memset(mem_.data() + kFbAt, kSentinel, kH * kFbStride);
    std::memset(mem_.data() + kDepthAt, kSentinel, kH * kW * 4);
  }
  // The planes in memory against `color` and `depth` (none: not compared); the colour rows'
  // padding untouched.
  void expect_planes(const std::vector<Rgba8>& color, const std::vector<uint32_t>& depth,
                     const char* what) {
    for (size_t i = 0; i < color.size(); ++i) {
      uint32_t c, d;
      const uint64_t row = kFbAt + i / kW * kFbStride;
      std::memcpy(&c, mem_.data() + row + i % kW * 4, 4);
      std::memcpy(&d, mem_.data() + kDepthAt + i * 4, 4);
      if (c != word_of(color[i]) || (!depth.empty() && d != depth[i]))
        throw Failed{fmt::format("{} ({}, {}): colour 0x{:x} depth 0x{:x}, expected 0x{:x} 0x{:x}",
                                 what, i % kW, i / kW, c, d, word_of(color[i]),
                                 depth.empty() ? 0 : depth[i])};
      if (i % kW == 0 && std::any_of(mem_.data() + row + kW * 4, mem_.data() + row + kFbStride,
                                     [](uint8_t b) { return b != kSentinel; }))
        throw Failed{fmt::format("{}: row {}'s padding written", what, i / kW)};
    }
  }

  void run();
};

void Tester::run() {
  // ---- 1. The register map ------------------------------------------------------------------
  check("id_version", [&] {
    expect_eq(rd(reg::kId), kIdValue, "ID");
    expect_eq(rd(reg::kVersion), kVersionValue, "VERSION");
  });
  check("reset_values", [&] {
    expect_eq(rw_registers().size(), 21, "RW registers");
    for (uint64_t a = reg::kStatus; a < reg::kSize; a += 4)  // RW, STATUS, counters ...
      if (!is_hole(a) && a != reg::kTileSize)
        expect_eq(rd(a), 0, fmt::format("0x{:x} at reset", a));
    expect(!irq.read(), "irq high at reset");
  });
  check("rw_write_read_back", [&] {
    for (uint64_t a : rw_registers())
      for (uint32_t v : {0xa5a5a5a5u, 0x5a5a5a5au, uint32_t(a), 0u}) {
        wr(a, v);
        expect_eq(rd(a), v, fmt::format("0x{:x} after writing 0x{:x}", a, v));
      }
    for (uint64_t lo : kPairs) {  // one half written: the other kept
      wr64(lo, 0x1122334455667788ull);
      wr(lo + 4, 0xcafef00d);
      expect_eq(rd64(lo), 0xcafef00d55667788ull, fmt::format("pair 0x{:x}", lo));
      wr(lo, 0x0badbeef);
      expect_eq(rd64(lo), 0xcafef00d0badbeefull, fmt::format("pair 0x{:x}", lo));
      wr64(lo, 0);
    }
  });
  check("ro_write_refused", [&] {
    std::vector<uint64_t> ro = {reg::kId, reg::kVersion, reg::kTileSize, reg::kErrorInfo,
                                reg::kPasses};
    for (uint64_t a = reg::kFragmentsInLo; a < reg::kSize; a += 4) ro.push_back(a);
    for (uint64_t a : ro) {
      const uint32_t before = rd(a);
      uint32_t v = ~before;
      expect_resp(access(kWr, a, v), tlm::TLM_COMMAND_ERROR_RESPONSE, fmt::format("RO 0x{:x}", a));
      expect_eq(rd(a), before, fmt::format("RO 0x{:x} after a write", a));
    }
  });
  check("command_status_tile_size", [&] {
    expect_eq(rd(reg::kCommand), 0, "COMMAND");
    wr(reg::kStatus, 0xffffffff);  // busy and the code are read-only: nothing is set
    expect_eq(rd(reg::kStatus), 0, "STATUS after writing ones while idle");
    const uint32_t t = rd(reg::kTileSize);
    expect(t != 0 && (t & (t - 1)) == 0, fmt::format("TILE_SIZE {} not a power of two", t));
  });

  // ---- 2. Base protocol ---------------------------------------------------------------------
  check("address_error", [&] {
    for (uint64_t a = 0; a < reg::kSize; a += 4) {  // the holes, and only they, unmapped
      uint32_t v = 0;
      expect_resp(access(kRd, a, v),
                  is_hole(a) ? tlm::TLM_ADDRESS_ERROR_RESPONSE : tlm::TLM_OK_RESPONSE,
                  fmt::format("read 0x{:x}", a));
    }
    for (uint64_t a : {uint64_t{0x3c}, uint64_t{0x74}, reg::kSize, uint64_t{0x1000},
                       uint64_t{0xfffffffffffffff0ull}, uint64_t{0x02}, reg::kFrameSize + 1})
      for (auto cmd : {kRd, kWr}) {
        uint32_t v = 0xffffffff;
        expect_resp(access(cmd, a, v), tlm::TLM_ADDRESS_ERROR_RESPONSE, fmt::format("0x{:x}", a));
      }
    expect_eq(rd(reg::kFrameSize), 0, "FRAME_SIZE after a misaligned write");
  });
  check("burst_byte_enable_error", [&] {
    uint8_t buf[8], be[4] = {0xff, 0xff, 0xff, 0xff};
    const char* const kinds[] = {"length 2", "length 8", "streaming width 2", "byte enables"};
    std::memset(buf, 0xff, sizeof buf);
    for (auto cmd : {kRd, kWr})
      for (int kind = 0; kind < 4; ++kind) {  // length 2, 8; streaming width 2; byte enables
        tlm::tlm_generic_payload tx;
        fill(tx, cmd, reg::kFrameSize, buf, kind == 0 ? 2 : kind == 1 ? 8 : 4);
        if (kind == 2) tx.set_streaming_width(2);
        if (kind == 3) tx.set_byte_enable_ptr(be), tx.set_byte_enable_length(4);
        expect_resp(transport(tx), kind == 3 ? tlm::TLM_BYTE_ENABLE_ERROR_RESPONSE
                                             : tlm::TLM_BURST_ERROR_RESPONSE,
                    fmt::format("{} with {}", cmd == kRd ? "read" : "write", kinds[kind]));
      }
    expect_eq(rd(reg::kFrameSize) | rd(reg::kFrameFormat), 0, "FRAME_SIZE/FORMAT after them");
  });
  check("ignore_command_ok", [&] {
    uint32_t v = uint32_t(Command::kBeginFrame);
    for (uint64_t a : {reg::kId, reg::kCommand})
      expect_resp(access(tlm::TLM_IGNORE_COMMAND, a, v), tlm::TLM_OK_RESPONSE, "ignore");
    expect_eq(rd(reg::kStatus), 0, "STATUS after an ignored COMMAND");
  });

  // ---- 3. transport_dbg ---------------------------------------------------------------------
  check("dbg_read", [&] {
    std::vector<uint32_t> map(reg::kSize / 4 + 2, 0xcccccccc);
    expect_eq(dbg(kRd, 0, map.data(), unsigned(map.size() * 4)), reg::kSize, "bytes of the map");
    expect_eq(map[0], kIdValue, "ID by debug");
    expect_eq(map[1], kVersionValue, "VERSION by debug");
    expect_eq(map[reg::kTileSize / 4], rd(reg::kTileSize), "TILE_SIZE by debug");
    expect_eq(map[reg::kSize / 4], 0xcccccccc, "a word past the map");
    expect_eq(dbg(kRd, 0x02, map.data(), 4), 0, "bytes at 0x02");
    expect_eq(dbg(kRd, 0, map.data(), 6), 0, "bytes of a 6-byte read");
    expect_eq(dbg(kWr, reg::kFrameSize + 2, map.data(), 4), 0, "bytes of a write at 0x12");
  });
  check("dbg_write", [&] {
    uint32_t v[2] = {0x00200030, 0x1234};
    expect_eq(dbg(kWr, reg::kFrameSize, v, 8), 8, "bytes");
    expect_eq(rd64(reg::kFrameSize), 0x0000123400200030ull, "FRAME_SIZE, FORMAT after it");
    expect_eq(dbg(kWr, reg::kTileOrigin, v, 8), 4, "bytes, up to RO TILE_SIZE");
    expect_eq(rd(reg::kTileOrigin), v[0], "TILE_ORIGIN after a debug write");
    for (uint64_t a : {reg::kFrameSize, reg::kFrameFormat, reg::kTileOrigin}) wr(a, 0);
    const uint64_t commands = rop_.totals().commands;
    v[0] = uint32_t(Command::kBeginFrame);
    expect_eq(dbg(kWr, reg::kCommand, v, 8), 0, "bytes at COMMAND");
    expect_eq(dbg(kWr, reg::kStatus, v, 4), 0, "bytes at STATUS");
    wait(1, SC_US);
    expect_eq(rd(reg::kStatus), 0, "STATUS after a debug COMMAND");
    expect(!irq.read(), "irq high after a debug COMMAND");
    expect_eq(rop_.totals().commands, commands, "commands run");
    expect_eq(rd(reg::kFrameSize), 0, "FRAME_SIZE (after COMMAND in the same debug write)");
  });

  // ---- 5a. Command errors before any frame --------------------------------------------------
  setup();
  check("err_order", [&] {
    wr(reg::kPassState, pack_state(RopState{}));
    exec(Command::kBeginPass, "BEGIN_PASS before any frame", ErrorCode::kOrder);
    exec(Command::kDraw, "DRAW outside a pass", ErrorCode::kOrder);
    exec(Command::kEndPass, "END_PASS outside a pass", ErrorCode::kOrder);
    exec(Command::kEndFrame, "END_FRAME outside a frame", ErrorCode::kOrder);
    exec(Command::kBeginFrame, "BEGIN_FRAME after them");
    exec(Command::kDraw, "DRAW in a frame, outside a pass", ErrorCode::kOrder);
    exec(Command::kEndPass, "END_PASS in a frame, outside a pass", ErrorCode::kOrder);
  });
  check("err_bad_command", [&] {
    for (uint32_t c : {0u, kLastCommand + 1, 0xffffffffu}) {
      exec(c, fmt::format("COMMAND {}", c), ErrorCode::kBadCommand);
      exec(Command::kBeginFrame, "BEGIN_FRAME after it");
    }
  });

  // ---- 4. A frame by registers: replace, depth less; the nearer wins, far ones lose ---------
  const std::vector<Fragment> frags = {
      {3, 5, 1000, {255, 0, 0, 255}}, {3, 5, 500, {0, 255, 0, 255}}, {3, 5, 800, {0, 0, 255, 255}},
      {31, 31, 0, {255, 255, 255, 255}}, {0, 0, kFar, {9, 9, 9, 9}}};  // far: not less than far
  check("frame_by_registers", [&] {
    std::vector<Rgba8> color(kW * kH, kClear);
    std::vector<uint32_t> depth(kW * kH, kFar);
    color[5 * kW + 3] = {0, 255, 0, 255}, depth[5 * kW + 3] = 500;
    color[31 * kW + 31] = {255, 255, 255, 255}, depth[31 * kW + 31] = 0;
    wipe_planes();
    const uint64_t passes = rop_.totals().passes;
    setup();
    exec(Command::kBeginFrame, "BEGIN_FRAME");
    wr(reg::kPassState, pack_state(RopState{}));
    exec(Command::kBeginPass, "BEGIN_PASS");
    put_fragments(frags);
    exec(Command::kDraw, "DRAW");
    exec(Command::kEndPass, "END_PASS");
    exec(Command::kEndFrame, "END_FRAME");
    expect_planes(color, depth, "memory");
    const Framebuffer& fb = rop_.framebuffer();
    expect(fb.width == kW && fb.height == kH, "framebuffer() size");
    expect_planes(fb.color, fb.depth, "memory against framebuffer()");
    expect_eq(rop_.totals().passes, passes + 1, "totals().passes");
  });
  check("frame_counters", [&] {
    expect_eq(rd(reg::kPasses), 1, "PASSES");
    expect_eq(rd64(reg::kFragmentsInLo), frags.size(), "FRAGMENTS_IN");
    expect_eq(rd64(reg::kFragmentsPassedLo), 3, "FRAGMENTS_PASSED");
    expect_eq(rd64(reg::kColorWritesLo), 3, "COLOR_WRITES");
    expect(rd64(reg::kCyclesLo) > 0, "CYCLES is 0");
    expect_eq(rd64(reg::kDmaBytesLo), frags.size() * kTraceFragmentBytes + 2 * kW * kH * 4,
              "DMA_BYTES (fragments, colour and depth)");
    expect(rd64(reg::kDmaTransactionsLo) >= 1, "DMA_TRANSACTIONS is 0");
  });
  check("status_irq_w1c", [&] {
    wr(reg::kCommand, uint32_t(Command::kBeginFrame));
    expect_eq(wait_idle("BEGIN_FRAME"), status::kDone, "STATUS after BEGIN_FRAME");
    wr(reg::kStatus, status::kError);  // the other bit: done stays, and the irq with it
    wait(1, SC_NS);
    expect_eq(rd(reg::kStatus), status::kDone, "STATUS after writing error back");
    expect(irq.read(), "irq low while done is set");
    wr(reg::kStatus, status::kDone);
    wait(1, SC_NS);
    expect_eq(rd(reg::kStatus), 0, "STATUS after writing done back");
    expect(!irq.read(), "irq high after done written back");
  });
  check("frame_op_tile_store", [&] {
    wipe_planes();
    wr(reg::kOpKind, uint32_t(FrameOpKind::kClearColor));
    wr(reg::kOpColor, 0x04030201);
    exec(Command::kFrameOp, "FRAME_OP clear colour");
    exec(Command::kTileStore, "TILE_STORE (0, 0)");
    expect_planes(std::vector<Rgba8>(kW * kH, Rgba8{1, 2, 3, 4}), {}, "after the tile store");
    wr(reg::kOpKind, kFrameOpKinds);
    exec(Command::kFrameOp, "OP_KIND past the last", ErrorCode::kBadSetup);
    wr(reg::kTileOrigin, 1);
    exec(Command::kTileStore, "TILE_ORIGIN not a tile corner", ErrorCode::kBadSetup);
    wr(reg::kTileOrigin, 0);
  });

  // A frame one and a half tiles wide: TILE_LOAD (T, 0) takes the clipped second tile from
  // memory, and a pass's depth test meets what it loaded.
  check("tile_load", [&] {
    const int t = int(rd(reg::kTileSize)), w = t + std::max(1, t / 2), h = std::min(t, 8);
    const uint32_t stride = uint32_t(w) * 4;
    const auto at = [&](uint64_t base, int x, int y) { return base + uint64_t(y) * stride + uint64_t(x) * 4; };
    const auto loaded = [](int x, int y) { return Rgba8{uint8_t(x), uint8_t(y), 7, 200}; };
    const auto loaded_z = [](int x, int y) { return uint32_t(1000 + x + 100 * y); };
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const uint32_t c = word_of(loaded(x, y)), z = loaded_z(x, y);
        std::memcpy(mem_.data() + at(kFbAt, x, y), &c, 4);
        std::memcpy(mem_.data() + at(kDepthAt, x, y), &z, 4);
      }
    setup();
    wr(reg::kFrameSize, uint32_t(w) | uint32_t(h) << 16);
    wr(reg::kFbStride, stride);
    wr(reg::kDepthStride, stride);
    exec(Command::kBeginFrame, "BEGIN_FRAME");
    exec(Command::kTileLoad, "TILE_LOAD (0, 0) before a frame's pass");  // then overwritten:
    wr(reg::kOpKind, uint32_t(FrameOpKind::kClearColor));
    wr(reg::kOpColor, word_of(kClear));
    exec(Command::kFrameOp, "FRAME_OP clear colour");
    wr(reg::kOpKind, uint32_t(FrameOpKind::kClearDepth));
    wr(reg::kOpDepth, kFar);
    exec(Command::kFrameOp, "FRAME_OP clear depth");
    wr(reg::kTileOrigin, uint32_t(t));
    exec(Command::kTileLoad, "TILE_LOAD (T, 0)");
    wr(reg::kPassState, pack_state(RopState{}));
    exec(Command::kBeginPass, "BEGIN_PASS");
    exec(Command::kTileLoad, "TILE_LOAD inside a pass", ErrorCode::kOrder);
    // Nearer than the loaded depth, farther than it, and on the cleared first tile.
    put_fragments({{uint16_t(t), 0, 500, {1, 2, 3, 255}},
                   {uint16_t(t + (w - t) - 1), uint16_t(h - 1), 5000, {4, 5, 6, 255}},
                   {0, 0, 5000, {7, 8, 9, 255}}});
    exec(Command::kDraw, "DRAW");
    exec(Command::kEndPass, "END_PASS");
    expect_eq(rd64(reg::kFragmentsPassedLo), 2, "FRAGMENTS_PASSED (the far one on the loaded tile fails)");
    for (int y = 0; y < h; ++y)  // the memory the frame is stored to: wiped
      for (int x = 0; x < w; ++x) {
        std::memset(mem_.data() + at(kFbAt, x, y), kSentinel, 4);
        std::memset(mem_.data() + at(kDepthAt, x, y), kSentinel, 4);
      }
    exec(Command::kEndFrame, "END_FRAME");
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        Rgba8 c = x < t ? kClear : loaded(x, y);
        uint32_t z = x < t ? kFar : loaded_z(x, y);
        if (x == t && y == 0) c = {1, 2, 3, 255}, z = 500;
        if (x == 0 && y == 0) c = {7, 8, 9, 255}, z = 5000;
        uint32_t got_c, got_z;
        std::memcpy(&got_c, mem_.data() + at(kFbAt, x, y), 4);
        std::memcpy(&got_z, mem_.data() + at(kDepthAt, x, y), 4);
        expect(got_c == word_of(c) && got_z == z,
               fmt::format("({}, {}): colour 0x{:x} depth {}, expected 0x{:x} {}", x, y, got_c,
                           got_z, word_of(c), z));
      }
    exec(Command::kTileLoad, "TILE_LOAD outside a frame", ErrorCode::kOrder);
    exec(Command::kBeginFrame, "BEGIN_FRAME");
    wr(reg::kTileOrigin, 1);
    exec(Command::kTileLoad, "TILE_ORIGIN not a tile corner", ErrorCode::kBadSetup);
    wr(reg::kTileOrigin, uint32_t(t) << 16);
    exec(Command::kTileLoad, "TILE_ORIGIN below the frame", ErrorCode::kBadSetup);
    // A depth word wider than the frame's: refused at its address, nothing loaded.
    wr(reg::kTileOrigin, uint32_t(t));
    const uint32_t wide = kFar + 1;
    std::memcpy(mem_.data() + at(kDepthAt, t, 1), &wide, 4);
    exec(Command::kTileLoad, "a depth word above 24 bits", ErrorCode::kBadTile);
    expect_eq(rd(reg::kErrorInfo), uint32_t(at(kDepthAt, t, 1)), "ERROR_INFO (its address)");
    exec(Command::kTileStore, "TILE_STORE after it");
    expect_eq(word_of(rop_.framebuffer().color_at(t, 0)), word_of(kClear), "colour after the refused load");
    wr64(reg::kFbAddrLo, kMemBytes - 64);
    exec(Command::kTileLoad, "TILE_LOAD past the memory's end", ErrorCode::kDma);
    wr(reg::kTileOrigin, 0);
    setup();
    exec(Command::kBeginFrame, "BEGIN_FRAME after it");
  });

  // ---- 5b. Command errors in and around a frame ---------------------------------------------
  check("err_frame_setup", [&] {
    const WboitFormat wb;
    const std::pair<uint64_t, uint32_t> bad[] = {
        {reg::kFrameSize, 0}, {reg::kFrameSize, 9000 | kH << 16}, {reg::kFrameSize, kW},
        {reg::kFrameFormat, 7 | kDefaultCoverageSamples << 8},  // depth bits below 8
        {reg::kFrameFormat, kDefaultDepthBits | 3 << 8},        // samples not a power of two
        {reg::kWboit, uint32_t(7 | wb.rev_bits << 8 | wb.weight_bits << 16)}};  // acc below 8
    for (const auto& [at, v] : bad) {
      setup();
      wr(at, v);
      exec(Command::kBeginFrame, fmt::format("0x{:x} = 0x{:x}", at, v), ErrorCode::kBadSetup);
    }
    setup();
    exec(Command::kBeginFrame, "BEGIN_FRAME after them");
  });
  check("err_pass_state", [&] {
    for (uint32_t bits : {uint32_t(pack_state(RopState{}) | 7u << 5), 0x10000u}) {  // blend 7
      wr(reg::kPassState, bits);
      exec(Command::kBeginPass, fmt::format("PASS_STATE 0x{:x}", bits), ErrorCode::kBadSetup);
    }
    wr(reg::kPassState, pack_state(RopState{}));
    exec(Command::kBeginPass, "BEGIN_PASS after them");
    exec(Command::kBeginPass, "BEGIN_PASS inside a pass", ErrorCode::kOrder);
    exec(Command::kRunStream, "RUN_STREAM inside a pass", ErrorCode::kOrder);
    exec(Command::kBeginFrame, "BEGIN_FRAME inside a pass", ErrorCode::kOrder);
  });
  check("err_bad_fragment", [&] {
    const uint64_t in = rd64(reg::kFragmentsInLo);
    const Fragment good{1, 1, 10, {1, 1, 1, 1}};
    put_fragments({good, good, {kW, 0, 10, {}}});
    exec(Command::kDraw, "fragment x = width", ErrorCode::kBadFragment);
    expect_eq(rd(reg::kErrorInfo), 2, "ERROR_INFO (its index)");
    put_fragments({{0, 0, kFar + 1, {}}, good});
    exec(Command::kDraw, "fragment z past 24 bits", ErrorCode::kBadFragment);
    expect_eq(rd(reg::kErrorInfo), 0, "ERROR_INFO (its index)");
    wr64(reg::kFragAddrLo, kMemBytes - 8);
    exec(Command::kDraw, "fragments past the memory's end", ErrorCode::kDma);
    expect_eq(rd(reg::kErrorInfo), uint32_t(kMemBytes - 8), "ERROR_INFO (the address)");
    put_fragments({good, good});
    exec(Command::kDraw, "DRAW after them");
    exec(Command::kEndPass, "END_PASS");
    expect_eq(rd64(reg::kFragmentsInLo), in + 2, "FRAGMENTS_IN: the failed DRAWs drew nothing");
  });
  check("err_dma_store", [&] {
    wr64(reg::kFbAddrLo, kMemBytes - 64);
    exec(Command::kEndFrame, "END_FRAME storing past the memory's end", ErrorCode::kDma);
    expect_eq(rd(reg::kErrorInfo), uint32_t(kMemBytes - 64), "ERROR_INFO (the address)");
    wr64(reg::kFbAddrLo, kFbAt);
    exec(Command::kEndFrame, "END_FRAME again");
    exec(Command::kBeginFrame, "BEGIN_FRAME after it");
  });
  Trace t;  // two passes: the frame above's fragments, then alpha over them
  t.width = kW;
  t.height = kH;
  t.clear_color = kClear;
  RopState alpha;
  alpha.blend = BlendMode::kAlpha;
  alpha.depth_write = false;
  t.passes.push_back({"opaque", {}, RopState{}, frags});
  t.passes.push_back(
      {"alpha", {}, alpha, {{3, 5, 100, {200, 0, 0, 128}}, {7, 7, 9, {0, 0, 250, 64}}}});
  const std::string stream = serialize_trace(t);
  check("err_bad_stream", [&] {
    std::memset(mem_.data() + kStreamAt, 0xab, 64);
    wr64(reg::kStreamAddrLo, kStreamAt);
    wr(reg::kStreamBytes, 64);
    exec(Command::kRunStream, "garbage", ErrorCode::kBadStream);
    expect_eq(rd(reg::kErrorInfo), 0, "ERROR_INFO (bad magic at 0)");
    // Faults after some passes: those ran, the frame is abandoned, memory is not written.
    const auto untouched = [&](const char* what) {
      const auto sentinel = [](uint8_t b) { return b == kSentinel; };
      expect(std::all_of(mem_.data() + kFbAt, mem_.data() + kFbAt + kH * kFbStride, sentinel) &&
                 std::all_of(mem_.data() + kDepthAt, mem_.data() + kDepthAt + kH * kW * 4, sentinel),
             fmt::format("{}: the framebuffer in memory was written", what));
    };
    wipe_planes();
    std::memcpy(mem_.data() + kStreamAt, stream.data(), stream.size());
    wr(reg::kStreamBytes, uint32_t(stream.size() - 7));
    exec(Command::kRunStream, "truncated trace", ErrorCode::kBadStream);
    const uint32_t at = rd(reg::kErrorInfo);
    expect(at > 0 && at < stream.size(), fmt::format("ERROR_INFO {} of {}", at, stream.size()));
    expect_eq(rd(reg::kPasses), 1, "PASSES (the first ran; the second's fragments are cut)");
    untouched("truncated trace");
    wr(reg::kStreamBytes, 0xffffffffu);  // read as it runs: the fault is the bytes after it
    exec(Command::kRunStream, "STREAM_BYTES 4 GiB", ErrorCode::kBadStream);
    expect_eq(rd(reg::kErrorInfo), uint32_t(stream.size()), "ERROR_INFO (the bytes after the trace)");
    untouched("STREAM_BYTES 4 GiB");
    // The alpha pass's first fragment (two records and the final operations' count from the
    // end) moved outside the frame.
    const size_t rec = stream.size() - 4 - 2 * kTraceFragmentBytes;
    mem_.data()[kStreamAt + rec] = 0xff, mem_.data()[kStreamAt + rec + 1] = 0xff;
    wr(reg::kStreamBytes, uint32_t(stream.size()));
    exec(Command::kRunStream, "a fragment outside the frame", ErrorCode::kBadStream);
    expect_eq(rd(reg::kErrorInfo), uint32_t(rec), "ERROR_INFO (the fragment's byte)");
    expect_eq(rd(reg::kPasses), 1, "PASSES (the first ran)");
    untouched("a fragment outside the frame");
    std::memcpy(mem_.data() + kStreamAt, stream.data(), stream.size());
    exec(Command::kRunStream, "the whole trace");
  });
  check("err_busy", [&] {
    wr(reg::kCommand, uint32_t(Command::kBeginFrame), false);
    wr(reg::kCommand, uint32_t(Command::kEndFrame), false);  // the first has not started yet
    uint32_t s = 0;
    expect_resp(access(kRd, reg::kStatus, s, false), tlm::TLM_OK_RESPONSE, "read STATUS");
    expect_eq(s, status::kBusy | code_of(ErrorCode::kBusy), "STATUS after a COMMAND while busy");
    expect_eq(rd(reg::kErrorInfo), uint32_t(Command::kEndFrame), "ERROR_INFO (the dropped one)");
    s = wait_idle("BEGIN_FRAME");
    // Done, and the dropped command still reported until written back.
    expect_eq(s, status::kDone | code_of(ErrorCode::kBusy), "STATUS after the running one ended");
    clear_status();
    expect_eq(rd(reg::kStatus), 0u, "STATUS written back (the error's code with it)");
    exec(Command::kEndFrame, "END_FRAME (the dropped one) written again");
  });

  // ---- 6. DMI: a RUN_STREAM frame, the memory's DMI taken back, the same frame again --------
  std::vector<uint8_t> first;
  const auto run_stream = [&] {
    wipe_planes();
    std::memcpy(mem_.data() + kStreamAt, stream.data(), stream.size());
    setup();
    wr64(reg::kStreamAddrLo, kStreamAt);
    wr(reg::kStreamBytes, uint32_t(stream.size()));
    exec(Command::kRunStream, "RUN_STREAM");
    expect_eq(rd(reg::kPasses), t.passes.size(), "PASSES");
    expect_planes(rop_.framebuffer().color, rop_.framebuffer().depth, "against framebuffer()");
    return std::vector<uint8_t>(mem_.data() + kFbAt, mem_.data() + kFbAt + kH * kFbStride);
  };
  check("dmi_stream", [&] {
    const RopTlmTotals before = rop_.totals();
    first = run_stream();
    expect(rop_.totals().dmi_grants >= 1, "no DMI grant");
    expect(rop_.totals().dmi_accesses > before.dmi_accesses, "no DMI access in the frame");
  });
  check("dmi_invalidate", [&] {
    const uint64_t inv = rop_.totals().dmi_invalidations;
    mem_.invalidate_dmi();
    expect_eq(rop_.totals().dmi_invalidations, inv + 1, "dmi_invalidations");
    mem_.invalidate_dmi();  // nothing held any more: not counted again
    expect_eq(rop_.totals().dmi_invalidations, inv + 1, "dmi_invalidations after a second call");
  });
  check("dmi_again", [&] {
    const RopTlmTotals before = rop_.totals();
    expect(run_stream() == first, "the frame differs from the first run's");
    expect_eq(rop_.totals().dmi_grants, before.dmi_grants + 1, "dmi_grants (asked again)");
    expect(rop_.totals().dmi_accesses > before.dmi_accesses, "no DMI access after the new grant");
    // The stream is read in place: the block asks for the pointer itself, no b_transport needed.
    expect_eq(rop_.totals().dma_transactions, before.dma_transactions, "dma_transactions");
  });

  sc_core::sc_stop();
}

}  // namespace

// SystemC prints its banner before sc_main unless told otherwise: main() is ours, then.
int main(int argc, char** argv) {
  setenv("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE", "1", 0);
  return sc_core::sc_elab_and_sim(argc, argv);
}

int sc_main(int argc, char** argv) {
  InsideKind inside = InsideKind::kGolden;
  if (!(argc == 1 ||
        (argc == 3 && std::string(argv[1]) == "--inside" && parse_inside(argv[2], inside)))) {
    std::fprintf(stderr, "usage: zblend_test_rop_tlm [--inside golden|rtl]\n");
    return 2;
  }
  // sc_stop() would report itself as an info.
  sc_core::sc_report_handler::set_actions("/OSCI/SystemC", sc_core::SC_INFO,
                                          sc_core::SC_DO_NOTHING);
  MemoryOptions mo;
  mo.bytes = kMemBytes;
  ZbVpMemory memory("memory", mo);
  RopTlmOptions ro;
  ro.inside = inside;
  ZbRopTlm rop("rop", ro);
  Tester tester("tester", rop, memory);
  sc_core::sc_signal<bool> irq("irq");
  tester.bus.bind(rop.regs);
  rop.dma.bind(memory.socket);
  rop.irq_o(irq);
  tester.irq(irq);
  sc_core::sc_start();
  std::printf("zblend_test_rop_tlm (%s inside): %d checks passed, %d failed\n", to_string(inside),
              tester.passed, tester.failed);
  return tester.failed ? 1 : 0;
}
