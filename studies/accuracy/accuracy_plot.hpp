// gnuplot files for `firn study accuracy`: per problem, error against dx (with the expected order)
// and against run time (with the Pareto front); for the two spheres, total energy against time per
// transfer scheme.
#pragma once

#include <string>
#include <vector>

#include "studies/accuracy/accuracy_study.hpp"
#include "studies/sweep/gnuplot.hpp"

namespace firn::study {

// Draws PROBLEM.png from the problem's rows (pareto marked). Colour: transfer and shape; filled
// points and solid lines: double, open points and dashes: float.
sweep::PlotFiles accuracy_plot(const AccuracyProblem& problem, const std::vector<AccuracyRow>& rows);

struct EnergySeries {
  std::string title;
  std::vector<double> time, total;  // kinetic + elastic (J)
};

// Draws two_spheres_energy.png: total energy / its initial value against time, one curve per series.
sweep::PlotFiles energy_history_plot(const std::vector<EnergySeries>& series);

}  // namespace firn::study
