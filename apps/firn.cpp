// The `firn` command line (DESIGN.md section 5): thin, it parses arguments and calls the engine.
#include <CLI/CLI.hpp>

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>

#include "apps/commands.hpp"
#include "engine/version.hpp"

namespace {

// How OpenMP's idle threads wait between the step's launches (issue 15). A launch on a team whose
// threads sleep (OMP_WAIT_POLICY=passive) first wakes them, and a thread that finishes early sleeps
// and is woken again at the end; the snowball pair's step has some 21 launches, and on 2 vCPUs
// under KVM those wake-ups cost it 5-13% of its speed and cube_drop 3-8% against threads that spin
// a while first (GOMP_SPINCOUNT=10000). Threads that spin take the cores other processes need,
// though: with another process busy on one of the two cores the same spin made both 8-13% slower
// than passive waiting, and libgomp's default spin of 300,000 about halved the pair (issue 15,
// docs/performance.md). So firn spins briefly where nothing else is running as it starts and waits
// passively otherwise, unless the user set OMP_WAIT_POLICY or GOMP_SPINCOUNT. libgomp reads them
// as it loads, before main, so firn sets one and restarts itself once.
constexpr const char* kSpinCount = "10000";

// Whether other tasks keep running: the fourth field of /proc/loadavg counts the tasks runnable at
// the moment it is read, this process among them, so the fewest over ten readings 1 ms apart is
// above one only where another task ran at each (the shell that started firn may still be runnable
// at the first).
bool others_running() {
  int fewest = 1 << 30;
  for (int i = 0; i < 10; ++i) {
    if (i > 0) usleep(1000);
    std::FILE* f = std::fopen("/proc/loadavg", "r");
    if (!f) return true;  // unknown: assume a shared machine
    double load[3];
    int runnable = 0, total = 0;
    const int read = std::fscanf(f, "%lf %lf %lf %d/%d", &load[0], &load[1], &load[2], &runnable, &total);
    std::fclose(f);
    if (read != 5) return true;
    fewest = std::min(fewest, runnable);
  }
  return fewest > 1;
}

void choose_openmp_waiting(char** argv) {
  if (std::getenv("OMP_WAIT_POLICY") || std::getenv("GOMP_SPINCOUNT")) return;
  if (others_running())
    setenv("OMP_WAIT_POLICY", "passive", 1);
  else
    setenv("GOMP_SPINCOUNT", kSpinCount, 1);
  execv("/proc/self/exe", argv);  // returns only if it failed: then carry on as we are
}

}  // namespace

int main(int argc, char** argv) {
  choose_openmp_waiting(argv);
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
