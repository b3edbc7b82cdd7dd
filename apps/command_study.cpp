// firn study accuracy|stability [--quick] [--out DIR] [--threads N] [--backend B]: the reports that turn "fast
// and accurate" into figures anyone can regenerate (DESIGN.md section 5).
#include "apps/commands.hpp"

namespace firn::app {

void add_study_command(CLI::App& app) {
  CLI::App* study = app.add_subcommand("study", "the accuracy and stability reports (CSV, summary, PNG plots)");
  study->require_subcommand(1);
  add_study_accuracy_command(*study);
  add_study_stability_command(*study);
}

}  // namespace firn::app
