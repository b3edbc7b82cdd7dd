// The `firn` command line (DESIGN.md section 5): thin, it parses arguments and calls the engine.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>

#include "apps/commands.hpp"
#include "apps/run_rendering.hpp"

int main(int argc, char** argv) {
  CLI::App app{"firn: a Material Point Method engine for snow, rubber tires and rigid bodies"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "firn 0.1.0");
  firn::app::add_bench_command(app);
  firn::app::add_verify_command(app);
  firn::app::add_run_command(app);
  firn::app::add_render_command(app);
  firn::app::add_check_command(app);
  firn::app::add_sweep_command(app);
  firn::app::add_help_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  return firn::app::exit_status();
}
