// The sweeps' rows as CSV, one row per point and method (or depth width), with a header.
#include <cmath>

#include <fmt/core.h>

#include "sweeps.h"

namespace zb::lab {

namespace {

constexpr const char* kErrorHeader =
    "rmse,psnr_db,max_abs,share_over_2,share_over_16,delta_e_mean,delta_e_max";

std::string error_fields(const ImageError& e) {
  return fmt::format("{:.4f},{},{},{:.6f},{:.6f},{:.4f},{:.3f}", e.rmse,
                     std::isinf(e.psnr) ? std::string("inf") : fmt::format("{:.3f}", e.psnr),
                     e.max_abs, e.share_over_2, e.share_over_16, e.delta_e_mean, e.delta_e_max);
}

}  // namespace

std::string orbit_csv(const std::vector<OrbitRow>& rows) {
  std::string out = fmt::format("step,angle_deg,method,popping,{}\n", kErrorHeader);
  for (const OrbitRow& r : rows)
    out += fmt::format("{},{:.4f},{},{:.6f},{}\n", r.step, r.angle_deg, r.method, r.popping,
                       error_fields(r.error));
  return out;
}

std::string depth_csv(const std::vector<DepthRow>& rows) {
  std::string out = "separation,method,depth_bits,near_pixels,far_shown,error,error_vs_reference\n";
  for (const DepthRow& r : rows)
    out += fmt::format("{:.6g},{},{},{},{},{:.6f},{:.6f}\n", r.separation, r.method,
                       r.depth_bits, r.near_pixels, r.far_shown, r.error, r.error_vs_reference);
  return out;
}

std::string method_csv(const char* x_name, const std::vector<MethodRow>& rows) {
  std::string out = fmt::format("{},scene,method,{}\n", x_name, kErrorHeader);
  for (const MethodRow& r : rows)
    out += fmt::format("{:.6g},{},{},{}\n", r.x, r.scene, r.method, error_fields(r.error));
  return out;
}

std::string wboit_csv(const std::vector<WboitRow>& rows) {
  std::string out = fmt::format(
      "scene,method,acc_bits,rev_bits,weight_bits,word_bits,bytes,{}\n", kErrorHeader);
  for (const WboitRow& r : rows) {
    const bool w = r.method == "wboit";
    out += fmt::format("{},{},{},{},{},{},{},{}\n", r.scene, r.method,
                       w ? std::to_string(r.format.acc_bits) : "",
                       w ? std::to_string(r.format.rev_bits) : "",
                       w ? std::to_string(r.format.weight_bits) : "",
                       w ? std::to_string(4 * r.format.acc_bits + r.format.rev_bits) : "",
                       r.bytes, error_fields(r.error));
  }
  return out;
}

std::string offset_csv(const std::vector<OffsetRow>& rows) {
  std::string out =
      "knob,value,default,scene,tilt_deg,edge_pixels,hidden_drawn,visible_missing,"
      "hidden_drawn_share,visible_missing_share\n";
  for (const OffsetRow& r : rows)
    out += fmt::format("{},{},{},{},{},{},{},{},{:.6f},{:.6f}\n", r.knob,
                       std::isinf(r.value) ? std::string("inf") : fmt::format("{}", r.value),
                       int(r.is_default), r.scene,
                       std::isnan(r.tilt) ? std::string() : fmt::format("{:g}", r.tilt),
                       r.error.edge_pixels, r.error.hidden_drawn, r.error.visible_missing,
                       r.error.hidden_drawn_share(), r.error.visible_missing_share());
  return out;
}

}  // namespace zb::lab
