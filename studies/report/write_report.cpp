#include "studies/report/write_report.hpp"

#include <filesystem>
#include <stdexcept>

#include "studies/report/run_report.hpp"
#include "studies/report/sweep_report.hpp"

namespace firn::report {

std::string write_report(const std::string& dir, const std::string& shipped_scenes, const sweep::SweepReport& report) {
  if (std::filesystem::exists(dir + "/sweep.args")) return write_sweep_report(dir, shipped_scenes, report);
  if (!std::filesystem::exists(dir + "/summary.json") && !std::filesystem::exists(dir + "/scene.resolved.toml"))
    throw std::invalid_argument(dir + ": not a run's output folder (summary.json, scene.resolved.toml) or a sweep's "
                                      "(sweep.args)");
  return write_run_report(dir);
}

}  // namespace firn::report
