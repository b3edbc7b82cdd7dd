#include "studies/sweep/slurm_sweep.hpp"

#include <cctype>
#include <filesystem>
#include <string>

#include "engine/output/atomic_file.hpp"
#include "studies/sweep/child_process.hpp"
#include "studies/sweep/run_record.hpp"
#include "studies/sweep/slurm_job.hpp"

namespace firn::sweep {

int submit_slurm_sweep(const SweepOptions& o, const SweepPlan& plan, const SweepReport& report) {
  const std::string out = std::filesystem::absolute(plan.out).lexically_normal().string();
  SweepPlan absolute = plan;
  absolute.out = out;
  SlurmJob job;
  job.name = "firn_sweep_" + std::filesystem::path(out).filename().string();
  job.slurm_output = out + "/slurm/task_%a.txt";
  job.sbatch_options = o.sbatch;
  const std::string self = self_executable();
  for (std::size_t i = 0; i < plan.combinations.size(); ++i) {
    std::filesystem::create_directories(run_dir(absolute, i));
    job.tasks.push_back({run_command(o, absolute, i, self), run_dir(absolute, i) + "/log.txt"});
  }
  std::filesystem::create_directories(out + "/slurm");
  const std::string script = out + "/slurm/sweep.sbatch";
  write_file_atomically(script, slurm_array_script(job));
  ChildSpec sbatch{{"sbatch", "--parsable", script}, out + "/slurm/sbatch.txt", out, true};
  const int status = wait_child(start_child(sbatch));
  std::string reply = file_text(sbatch.log_path).value_or("");
  while (!reply.empty() && std::isspace(static_cast<unsigned char>(reply.back()))) reply.pop_back();
  if (status != 0) {
    report("sbatch " + script + " failed (exit status " + std::to_string(status) +
           (status == 127 ? ", is Slurm's sbatch installed?" : "") + "): " + reply);
    return 1;
  }
  report("submitted Slurm job array " + reply.substr(0, reply.find(';')) + " (" +
         std::to_string(plan.combinations.size()) + " runs, " + script +
         "); when it has finished: firn sweep --collect " + out);
  return 0;
}

}  // namespace firn::sweep
