/* zb_golden_dpi.h: the C side of zb_golden_pkg.sv's DPI-C imports, declared exactly as a DPI
 * simulator declares them (Verilator's generated __Dpi.h: chandle is void*, int unsigned is
 * unsigned int, longint unsigned is unsigned long long, outputs are pointers, string is
 * const char*). Each forwards to the C API of the same name in zb_golden.h, whose handle is typed;
 * tests/conformance compiles this header against Verilator's __Dpi.h, so a mismatch is a compile
 * error. */
#ifndef ZB_GOLDEN_DPI_H_
#define ZB_GOLDEN_DPI_H_

#ifdef __cplusplus
extern "C" {
#endif

int zb_dpi_create(void** handle, int width, int height, int depth_bits, int coverage_samples,
                  unsigned int clear_rgba);
void zb_dpi_destroy(void* handle);
int zb_dpi_set_wboit(void* handle, int acc_bits, int rev_bits, int weight_bits);
int zb_dpi_set_arithmetic(void* handle, const char* name);
int zb_dpi_begin_pass(void* handle, unsigned int state);
int zb_dpi_push(void* handle, int x, int y, unsigned int z, unsigned int rgba, int coverage,
                unsigned int* wrote, unsigned int* depth, unsigned int* coverage_out,
                unsigned int* rgba_out);
int zb_dpi_end_pass(void* handle, unsigned long long* fragments_in,
                    unsigned long long* fragments_passed, unsigned long long* depth_reads,
                    unsigned long long* depth_writes, unsigned long long* color_reads,
                    unsigned long long* color_writes);
int zb_dpi_frame_op(void* handle, int kind, unsigned int value_rgba, unsigned int depth);
int zb_dpi_read(void* handle, int plane, int x, int y, unsigned int* value);
const char* zb_dpi_last_error(void* handle);

#ifdef __cplusplus
}
#endif

#endif /* ZB_GOLDEN_DPI_H_ */
