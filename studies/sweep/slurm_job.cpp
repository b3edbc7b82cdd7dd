#include "studies/sweep/slurm_job.hpp"

#include <stdexcept>

namespace firn::sweep {

std::string shell_quoted(const std::string& word) {
  std::string q = "'";
  for (const char c : word) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

std::string slurm_array_script(const SlurmJob& job) {
  if (job.tasks.empty()) throw std::invalid_argument("a Slurm job array needs at least one task");
  std::string s = "#!/bin/bash\n"
                  "# Written by firn sweep --scheduler slurm: array task I runs run I of the sweep.\n"
                  "#SBATCH --job-name=" + job.name + "\n"
                  "#SBATCH --array=1-" + std::to_string(job.tasks.size()) + "\n"
                  "#SBATCH --output=" + job.slurm_output + "\n";
  for (const std::string& o : job.sbatch_options) s += "#SBATCH " + o + "\n";
  s += "case \"$SLURM_ARRAY_TASK_ID\" in\n";
  for (std::size_t i = 0; i < job.tasks.size(); ++i) {
    s += "  " + std::to_string(i + 1) + ") exec";
    for (const std::string& a : job.tasks[i].argv) s += " " + shell_quoted(a);
    s += " --threads \"${SLURM_CPUS_PER_TASK:-1}\" >" + shell_quoted(job.tasks[i].log_path) + " 2>&1 ;;\n";
  }
  s += "  *) echo \"firn sweep: no run $SLURM_ARRAY_TASK_ID in this array\" >&2; exit 2 ;;\nesac\n";
  return s;
}

}  // namespace firn::sweep
