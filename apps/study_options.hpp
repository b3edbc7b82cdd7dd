// Options shared by the `firn study` reports (accuracy, stability).
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "apps/backend_option.hpp"

namespace firn::app {

struct StudyOptions {
  bool quick = false;  // a representative subset that finishes in under 3 minutes on 2 cores
  std::string out;     // the report's folder
  int threads = 0;     // OpenMP threads per run (0: all cores)
  std::string backend = "openmp";  // apps/backend_option.hpp
};

inline void add_study_options(CLI::App& command, StudyOptions& o) {
  command.add_flag("--quick", o.quick, "a representative subset (under 3 minutes on 2 cores)");
  command.add_option("--out", o.out, "folder for the CSV, the summary and the plots")->capture_default_str();
  command.add_option("--threads", o.threads, "OpenMP threads per run (default: all cores)")
      ->check(CLI::PositiveNumber);
  add_backend_option(&command, o.backend);
}

}  // namespace firn::app
