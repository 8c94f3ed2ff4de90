#include "zb_rop_inside.h"

#include "rop/rop.h"
#include "rtl_params.h"
#include "rtl_rop.h"
#include "sizing_cost.h"

namespace zb::vp {

const char* to_string(InsideKind k) { return k == InsideKind::kGolden ? "golden" : "rtl"; }

bool parse_inside(const std::string& name, InsideKind& out) {
  for (InsideKind k : {InsideKind::kGolden, InsideKind::kRtl}) {
    if (name == to_string(k)) {
      out = k;
      return true;
    }
  }
  return false;
}

namespace {

class GoldenInside final : public RopInside {
 public:
  Backend& backend() override { return counter_; }
  uint64_t cycles() const override { return counter_.cost().at(kRtlTileW).rtl_cycles(); }

 private:
  GoldenRop rop_;
  CostCounter counter_{rop_, kRtlBeat, CostScope::kPassSchedule};
};

class RtlInside final : public RopInside {
 public:
  Backend& backend() override { return rop_; }
  uint64_t cycles() const override { return rop_.total_cycles(); }

 private:
  RtlRop rop_;
};

}  // namespace

std::unique_ptr<RopInside> make_inside(InsideKind kind) {
  if (kind == InsideKind::kGolden) return std::make_unique<GoldenInside>();
  return std::make_unique<RtlInside>();
}

}  // namespace zb::vp
