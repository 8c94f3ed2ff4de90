// zblend: render scenes through the golden model with each transparency method.
#include <cstdio>
#include <exception>

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
  zb::app::add_sweep_command(app);
  zb::app::add_conformance_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "%s\n", zb::app::parse_error_line(app, e).c_str());
    return 2;
  } catch (const zb::app::UsageError& e) {
    std::fprintf(stderr, "zblend: error: %s\n", e.what());
    return 2;
  } catch (const zb::app::VerificationError& e) {
    std::fprintf(stderr, "zblend: FAILED: %s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "zblend: internal error: %s\n", e.what());
    return 1;
  }
  return 0;
}
