// firn verify [NAME]... [--threads N] [--backend serial|openmp|cuda]
// Runs known-answer problems (by default all but those run only on request, such as
// incline_rolling_fine); prints CSV on stdout with the header
// problem,level,dx,particles_per_cell,steps,error,bound,seconds and exits 0 only if every error is
// within its bound. Histories (energy per transfer scheme) go to standard error.
#include <cstdio>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "apps/backend_option.hpp"
#include "apps/commands.hpp"
#include "engine/verification/verification.hpp"

namespace firn::app {

void add_verify_command(CLI::App& app) {
  struct Options {
    std::vector<std::string> names;
    int threads = 0;
    std::string backend = "openmp";
  };
  auto opts = std::make_shared<Options>();
  CLI::App* verify = app.add_subcommand("verify", "run known-answer problems and check their errors");
  std::vector<std::string> known = verification_problems();
  for (const std::string& name : verification_problems_on_request()) known.push_back(name);
  verify->add_option("names", opts->names, "problems to run (default: all but those run only on request)")
      ->check(CLI::IsMember(known));
  verify->add_option("--threads", opts->threads, "OpenMP threads (default: all cores)")->check(CLI::PositiveNumber);
  add_backend_option(verify, opts->backend);
  verify->callback([opts]() {
    const std::optional<BackendKind> backend = usable_backend(opts->backend);
    if (!backend) return;
    VerificationOptions options;
    options.backend = *backend;
    options.threads = opts->threads;
    options.log = &std::cerr;
    const std::vector<std::string> names = opts->names.empty() ? verification_problems() : opts->names;
    std::printf("problem,level,dx,particles_per_cell,steps,error,bound,seconds\n");
    int failed = 0;
    for (const std::string& name : names)
      for (const VerificationRow& r : run_verification(name, options)) {
        std::printf("%s,%d,%.6g,%d,%ld,%.6g,%.6g,%.3f\n", r.problem.c_str(), r.level, r.dx, r.particles_per_cell,
                    r.steps, r.error, r.bound, r.seconds);
        std::fflush(stdout);
        if (!r.passed()) {
          std::fprintf(stderr, "firn verify: %s level %d: error %.6g exceeds its bound %.6g\n", r.problem.c_str(),
                       r.level, r.error, r.bound);
          ++failed;
        }
      }
    set_exit_status(failed ? 1 : 0);
  });
}

}  // namespace firn::app
