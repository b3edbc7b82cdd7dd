// firn study accuracy|stability: the measured reports of DESIGN.md section 6. On this branch only
// the stability study is registered; main's version adds the accuracy study.
#include "apps/commands.hpp"

namespace firn::app {

void add_study_command(CLI::App& app) {
  CLI::App* study = app.add_subcommand("study", "the stability report (CSV, summary and plots)");
  study->require_subcommand(1);
  add_study_stability_command(*study);
}

}  // namespace firn::app
