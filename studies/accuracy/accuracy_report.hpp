// What `firn study accuracy` writes: accuracy.csv (one row per case) and accuracy.md (per problem,
// the observed convergence order of each method and the Pareto front of error against run time).
#pragma once

#include <string>
#include <vector>

#include "studies/accuracy/accuracy_study.hpp"

namespace firn::study {

// Header: problem,level,dx,particles_per_cell,transfer,shape,precision,particles,steps,error,seconds,
// particle_steps_per_second,pareto,status
std::string accuracy_csv(const std::vector<AccuracyRow>& rows);

// Markdown; `rows` may hold any subset of the problems.
std::string accuracy_summary(const std::vector<AccuracyProblem>& problems, const std::vector<AccuracyRow>& rows,
                             const std::string& energy_loss_line);

}  // namespace firn::study
