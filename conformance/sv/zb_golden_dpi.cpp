// The DPI-C layer: zb_golden_pkg.sv's imports, forwarded to the C API. Only the types change
// (void* for the typed handle, DPI's integer types for <stdint.h>'s), so the C API keeps a
// typed handle for C callers and the simulator sees exactly the prototypes it generates.
#include "zb_golden_dpi.h"

#include <cstdint>
#include <type_traits>

#include "zb_golden.h"

// DPI's 32-bit integers are the C API's: the pointers below are passed through unconverted.
static_assert(std::is_same_v<unsigned int, uint32_t>, "DPI's int unsigned must be uint32_t");

namespace {

zb_golden* golden(void* handle) { return static_cast<zb_golden*>(handle); }

}  // namespace

extern "C" {

int zb_dpi_create(void** handle, int width, int height, int depth_bits, int coverage_samples,
                  unsigned int clear_rgba) {
  zb_golden* g = nullptr;
  const int status = zb_golden_create(handle ? &g : nullptr, width, height, depth_bits,
                                      coverage_samples, clear_rgba);
  if (handle) *handle = g;
  return status;
}

void zb_dpi_destroy(void* handle) { zb_golden_destroy(golden(handle)); }

int zb_dpi_set_wboit(void* handle, int acc_bits, int rev_bits, int weight_bits) {
  return zb_golden_set_wboit(golden(handle), acc_bits, rev_bits, weight_bits);
}

int zb_dpi_set_arithmetic(void* handle, const char* name) {
  return zb_golden_set_arithmetic(golden(handle), name);
}

int zb_dpi_begin_pass(void* handle, unsigned int state) {
  return zb_golden_begin_pass(golden(handle), state);
}

int zb_dpi_push(void* handle, int x, int y, unsigned int z, unsigned int rgba, int coverage,
                unsigned int* wrote, unsigned int* depth, unsigned int* coverage_out,
                unsigned int* rgba_out) {
  return zb_golden_push(golden(handle), x, y, z, rgba, coverage, wrote, depth, coverage_out,
                        rgba_out);
}

int zb_dpi_end_pass(void* handle, unsigned long long* fragments_in,
                    unsigned long long* fragments_passed, unsigned long long* depth_reads,
                    unsigned long long* depth_writes, unsigned long long* color_reads,
                    unsigned long long* color_writes) {
  // DPI's unsigned long long need not be uint64_t's type: copied, 0 when the call fails.
  uint64_t v[6] = {};
  const int status = zb_golden_end_pass(golden(handle), &v[0], &v[1], &v[2], &v[3], &v[4], &v[5]);
  unsigned long long* const out[6] = {fragments_in, fragments_passed, depth_reads,
                                      depth_writes, color_reads, color_writes};
  for (int i = 0; i < 6; ++i)
    if (out[i]) *out[i] = v[i];
  return status;
}

int zb_dpi_frame_op(void* handle, int kind, unsigned int value_rgba, unsigned int depth) {
  return zb_golden_frame_op(golden(handle), kind, value_rgba, depth);
}

int zb_dpi_read(void* handle, int plane, int x, int y, unsigned int* value) {
  return zb_golden_read(golden(handle), plane, x, y, value);
}

const char* zb_dpi_last_error(void* handle) { return zb_golden_last_error(golden(handle)); }

}  // extern "C"
