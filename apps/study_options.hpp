// The command-line options shared by the `firn study` reports (accuracy, stability).
#pragma once

#include <CLI/CLI.hpp>

#include "apps/backend_option.hpp"
#include "studies/study_options.hpp"

namespace firn::app {

inline void add_study_options(CLI::App& command, study::StudyOptions& o) {
  command.add_flag("--quick", o.quick, "a representative subset (under 3 minutes on 2 cores)");
  command.add_option("--out", o.out, "folder for the CSV, the summary and the plots")->capture_default_str();
  command.add_option("--threads", o.threads, "OpenMP threads per run (default: all cores)")
      ->check(CLI::PositiveNumber);
  add_backend_option(&command, o.backend);
}

}  // namespace firn::app
