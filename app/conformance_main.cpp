// zblend-conformance: `zblend conformance export | check` alone, without the RTL model: the
// conformance kit's program (make kit; docs/conformance.md).
#include "cli.h"
#include "commands.h"

int main(int argc, char** argv) {
  CLI::App app{"zblend-conformance: the conformance kit's vectors: export zblend's suite, check "
               "a DUT's planes against it"};
  app.name("zblend-conformance");
  app.require_subcommand(1, 1);
  zb::app::add_conformance_commands(app);
  return zb::cli::run_main(app, argc, argv);
}
