// What runs inside ZbRopTlm (docs/systemc.md "Two insides"): a Backend and the clock cycles it
// has spent, from the golden model timed by the lab's cost model or from the Verilated zb_rop.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "rop/backend.h"

namespace zb::vp {

enum class InsideKind { kGolden, kRtl };
const char* to_string(InsideKind k);
// "golden" or "rtl"; false for another name.
bool parse_inside(const std::string& name, InsideKind& out);

class RopInside {
 public:
  virtual ~RopInside() = default;
  virtual Backend& backend() = 0;
  // Clock cycles spent since construction: after each pass, the pass's cycles are counted.
  // Golden: the cost model's RTL cycles at zb_rop's tile (app/lab/sizing_cost.h, the pass
  // schedule: streaming and tile port). RTL: the Verilated zb_rop's clock cycles.
  // A frame or pass the inside cannot take throws std::invalid_argument from the backend's
  // begin_frame or begin_pass (the RTL's widths are those it was Verilated with).
  virtual uint64_t cycles() const = 0;
};

std::unique_ptr<RopInside> make_inside(InsideKind kind);

}  // namespace zb::vp
