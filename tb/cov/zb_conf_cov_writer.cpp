// zb_conf_cov_writer.sv's DPI-C function: the model's coverage, per instance (the coverage
// plan's generate loops), as verilator_coverage reads it.
#include "verilated.h"
#include "verilated_cov.h"

extern "C" void zb_cov_write(const char* path) {
  VerilatedCovContext* cov = Verilated::threadContextp()->coveragep();
  cov->forcePerInstance(true);
  cov->write(path);
}
