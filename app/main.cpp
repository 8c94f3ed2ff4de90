// zblend: render scenes through the golden model with each transparency method.
#include "cli.h"
#include "commands.h"

int main(int argc, char** argv) {
  CLI::App app{"zblend: a pixel back-end reference model that renders opaque and "
               "semi-transparent geometry without sorting"};
  app.name("zblend");
  app.require_subcommand(1, 1);
  zb::app::add_render_command(app);
  zb::app::add_trace_command(app);
  zb::app::add_info_commands(app);
  zb::app::add_lab_command(app);
  zb::app::add_pixel_command(app);
  zb::app::add_sweep_command(app);
  zb::app::add_conformance_command(app);
  return zb::cli::run_main(app, argc, argv);
}
