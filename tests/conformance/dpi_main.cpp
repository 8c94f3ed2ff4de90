// Runs tb_golden_dpi (its initial block does the work): exit 0 when it ends in $finish, 1 when
// it stops on a failed check. Including the generated __Dpi.h beside zb_golden_dpi.h proves the
// DPI layer's prototypes are the ones Verilator expects: a mismatch does not compile.
#include <cstdio>
#include <memory>

#include "Vtb_golden_dpi.h"
#include "Vtb_golden_dpi__Dpi.h"
#include "verilated.h"
#include "zb_golden_dpi.h"

int main(int argc, char** argv) {
  const auto context = std::make_unique<VerilatedContext>();
  context->commandArgs(argc, argv);
  context->fatalOnError(false);  // $stop: record the error and return, not abort
  const auto top = std::make_unique<Vtb_golden_dpi>(context.get());
  for (int i = 0; i < 4 && !context->gotFinish(); ++i) top->eval();
  top->final();
  if (!context->gotFinish()) {
    std::fprintf(stderr, "dpi_main: tb_golden_dpi did not finish\n");
    return 1;
  }
  return context->gotError() ? 1 : 0;
}
