// The `firn` command line (DESIGN.md section 5): thin, it parses arguments and calls the engine.
#include <CLI/CLI.hpp>

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <exception>

#include "apps/commands.hpp"
#include "engine/version.hpp"

namespace {

// OpenMP threads that spin while they wait make a run several times slower when other processes
// share the cores, and passive waiting costs nothing measurable on idle cores (cube_drop, 2
// threads: 12.3-14.0M particle-steps/s spinning against 12.5-13.2M passive when idle; 3.7-4.0M
// against 7.0-7.2M with a compiler busy on one of the two cores). libgomp reads OMP_WAIT_POLICY as
// it loads, before main, so firn sets it and restarts itself once, unless the user chose a policy.
void prefer_passive_openmp_waiting(char** argv) {
  if (std::getenv("OMP_WAIT_POLICY") || std::getenv("GOMP_SPINCOUNT")) return;
  setenv("OMP_WAIT_POLICY", "passive", 1);
  execv("/proc/self/exe", argv);  // returns only if it failed: then carry on as we are
}

}  // namespace

int main(int argc, char** argv) {
  prefer_passive_openmp_waiting(argv);
  CLI::App app{"firn: a Material Point Method engine for snow, rubber tires and rigid bodies"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("firn ") + firn::firn_version());
  firn::app::add_bench_command(app);
  firn::app::add_verify_command(app);
  firn::app::add_run_command(app);
  firn::app::add_render_command(app);
  firn::app::add_check_command(app);
  firn::app::add_sweep_command(app);
  firn::app::add_report_command(app);
  firn::app::add_study_command(app);
  firn::app::add_help_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int status = app.exit(e);  // prints help, the version or the error
    return status == 0 ? 0 : 2;       // every command-line mistake is bad input (commands.hpp)
  }
  return firn::app::exit_status();
}
