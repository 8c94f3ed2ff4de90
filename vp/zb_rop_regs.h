// ZbRopTlm's register map (docs/systemc.md "Register map"): the one source of its offsets, fields
// and codes, for the model, the host and the tests. 32-bit registers, little-endian, word aligned.
#pragma once

#include <cstdint>

namespace zb::vp {

namespace reg {
constexpr uint64_t kId = 0x00;           // RO: kIdValue
constexpr uint64_t kVersion = 0x04;      // RO: kVersionValue
constexpr uint64_t kStatus = 0x08;       // RO bits 0 busy; W1C bits 1 done, 2 error; RO [15:8] error code
constexpr uint64_t kCommand = 0x0c;      // WO: a Command starts; reads 0
constexpr uint64_t kFrameSize = 0x10;    // RW: width [15:0], height [31:16]
constexpr uint64_t kFrameFormat = 0x14;  // RW: depth bits [7:0], coverage samples [15:8]
constexpr uint64_t kWboit = 0x18;        // RW: accumulation [7:0], revealage [15:8], weight [23:16] bits
constexpr uint64_t kClearColor = 0x1c;   // RW: r [7:0], g [15:8], b [23:16], a [31:24]
constexpr uint64_t kPassState = 0x20;    // RW: the 16-bit pass state register (docs/datapath.md)
constexpr uint64_t kFragAddrLo = 0x24;   // RW: DRAW's fragments in memory (20-byte records)
constexpr uint64_t kFragAddrHi = 0x28;
constexpr uint64_t kFragCount = 0x2c;    // RW
constexpr uint64_t kOpKind = 0x30;       // RW: FRAME_OP's kind (FrameOpKind)
constexpr uint64_t kOpColor = 0x34;      // RW: its colour, as kClearColor
constexpr uint64_t kOpDepth = 0x38;      // RW: its depth
constexpr uint64_t kFbAddrLo = 0x40;     // RW: the colour framebuffer in memory, RGBA8 a pixel
constexpr uint64_t kFbAddrHi = 0x44;
constexpr uint64_t kFbStride = 0x48;     // RW: bytes a row
constexpr uint64_t kDepthAddrLo = 0x4c;  // RW: the depth plane in memory, 32 bits a pixel (0: none)
constexpr uint64_t kDepthAddrHi = 0x50;
constexpr uint64_t kDepthStride = 0x54;  // RW
constexpr uint64_t kTileOrigin = 0x58;   // RW: TILE_STORE's tile, x [15:0], y [31:16] in pixels
constexpr uint64_t kTileSize = 0x5c;     // RO: the tile's edge in pixels
constexpr uint64_t kStreamAddrLo = 0x60;  // RW: RUN_STREAM's command stream (a trace) in memory
constexpr uint64_t kStreamAddrHi = 0x64;
constexpr uint64_t kStreamBytes = 0x68;   // RW
constexpr uint64_t kErrorInfo = 0x6c;     // RO: the failing stream's byte offset, or DMA address low
constexpr uint64_t kPasses = 0x70;        // RO: passes run since BEGIN_FRAME
// RO 64-bit counters since BEGIN_FRAME, low word first (reading the low word latches nothing:
// read them while the ROP is idle).
constexpr uint64_t kFragmentsInLo = 0x78;
constexpr uint64_t kFragmentsPassedLo = 0x80;
constexpr uint64_t kColorWritesLo = 0x88;
constexpr uint64_t kCyclesLo = 0x90;        // the inside's clock cycles
constexpr uint64_t kDmaBytesLo = 0x98;      // bytes read and written on the initiator socket
constexpr uint64_t kDmaTransactionsLo = 0xa0;  // b_transport calls (DMI accesses not counted)
constexpr uint64_t kSize = 0xa8;            // the map's extent: addresses at or above are unmapped
// Unmapped words within it: 0x3c, 0x74.

// The read-write registers: the words from FRAME_SIZE to STREAM_BYTES but the hole and
// TILE_SIZE. The model keeps them as words and reads its fields out of them.
constexpr bool read_write(uint64_t a) {
  return a % 4 == 0 && a >= kFrameSize && a <= kStreamBytes && a != 0x3c && a != kTileSize;
}
}  // namespace reg

// A colour register's word (CLEAR_COLOR, OP_COLOR) is zb_rop's port word: pack_rgba (tile_io.h).

constexpr uint32_t kIdValue = 0x5a424c44;  // "ZBLD"
constexpr uint32_t kVersionValue = 1;

enum class Command : uint32_t {
  kBeginFrame = 1,  // a frame of kFrameSize, kFrameFormat, kWboit, cleared to kClearColor
  kBeginPass = 2,   // a pass of kPassState
  kDraw = 3,        // kFragCount fragments from kFragAddr into the pass
  kEndPass = 4,     // the pass runs
  kFrameOp = 5,     // kOpKind with kOpColor, kOpDepth, between passes
  kEndFrame = 6,    // the frame ends (final operations done): every tile stored to memory
  kTileStore = 7,   // the tile at kTileOrigin stored to memory, between passes
  kRunStream = 8,   // a whole frame from the trace at kStreamAddr: BEGIN_FRAME to END_FRAME
  kTileLoad = 9,    // the tile at kTileOrigin loaded from memory, between passes
};
constexpr uint32_t kLastCommand = uint32_t(Command::kTileLoad);

namespace status {
constexpr uint32_t kBusy = 1u << 0;
constexpr uint32_t kDone = 1u << 1;
constexpr uint32_t kError = 1u << 2;
constexpr int kCodeShift = 8;
}  // namespace status

// STATUS [15:8] after an error; the command that failed changed nothing it had not done yet.
enum class ErrorCode : uint32_t {
  kNone = 0,
  kBadCommand = 1,  // not a Command
  kBusy = 2,        // a command written while one runs (it is dropped)
  kOrder = 3,       // out of order: a pass outside a frame, DRAW outside a pass, ...
  kBadSetup = 4,    // a register's value out of range for the command (or for the inside)
  kBadStream = 5,   // RUN_STREAM's trace is malformed (kErrorInfo: the byte)
  kDma = 6,         // the memory answered a DMA access with an error (kErrorInfo: the address)
  kBadFragment = 7,  // DRAW's fragment outside the frame or its formats (kErrorInfo: its index)
  kBadTile = 8,      // TILE_LOAD's depth word above the frame's depth width (kErrorInfo: its address)
};

}  // namespace zb::vp
