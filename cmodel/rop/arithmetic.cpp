#include "arithmetic.h"

namespace zb {

namespace {

constexpr const char* kDivideNames[kDivides] = {"zblend", "round255", "floor256", "ceil256",
                                                "round256"};

}  // namespace

std::string to_string(const Arithmetic& r) {
  if (r.is_zblend()) return "zblend";
  std::string s = r.round == BlendRound::kSum ? "sum-" : "each-";
  s += kDivideNames[static_cast<unsigned>(r.divide)];
  if (r.one == One::k256) s += "-one256";
  return s;
}

Arithmetic arithmetic_at(unsigned i) {
  Arithmetic r;
  r.one = static_cast<One>(i % 2);
  r.divide = static_cast<Divide>((i / 2) % kDivides);
  r.round = static_cast<BlendRound>((i / (2 * kDivides)) % 2);
  return r;
}

std::optional<Arithmetic> parse_arithmetic(const std::string& name) {
  for (unsigned i = 0; i < kArithmetics; ++i) {
    const Arithmetic r = arithmetic_at(i);
    if (to_string(r) == name || (r.is_zblend() && name == "each-zblend")) return r;
  }
  return std::nullopt;
}

std::string arithmetic_error(const std::string& name) {
  return "'" + name + "' is not an arithmetic: zblend, or <each|sum>-<zblend|round255|floor256|" +
         "ceil256|round256>[-one256] (docs/datapath.md \"Declared arithmetic\")";
}

}  // namespace zb
