// firn study accuracy: every known-answer problem at each of its resolution levels with every
// method (transfer scheme x shape function x precision, at the problem's fixed CFL number),
// written to the report's folder:
//   accuracy.csv            one row per case (error, run time, particle-steps/s, Pareto flag),
//                           rewritten after every case so an interrupted study keeps what it ran;
//   accuracy.md             observed orders and the Pareto front per problem;
//   PROBLEM.png             error against dx and against run time (gnuplot; .dat and .gp beside it);
//   two_spheres_energy.png  total energy against time for APIC, PIC and FLIP.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "studies/study_options.hpp"

namespace firn::study {

struct AccuracyStudyOptions {
  StudyOptions study{false, "out/study/accuracy", 0};
  std::vector<std::string> problems;                      // empty: all
  std::string scenes;                                     // the shipped scene folder (snowball_pair_energy)
  std::function<void(const std::string& line)> progress;  // one line per case
};

struct AccuracyStudyResult {
  std::size_t cases = 0;
  double seconds = 0;
  bool plotted = true;  // every plot was drawn
};

// Runs the study into o.study.out, a folder that exists.
AccuracyStudyResult run_accuracy_study(const AccuracyStudyOptions& o);

}  // namespace firn::study
