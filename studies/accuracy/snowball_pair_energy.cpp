#include "studies/accuracy/snowball_pair_energy.hpp"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <ostream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include "engine/output/atomic_file.hpp"
#include "engine/scene/scene_run.hpp"
#include "engine/stability_guard.hpp"
#include "studies/sweep/metrics_history.hpp"

namespace firn::study {
namespace {

// A fresh folder under the system's temporary directory for one run's outputs, removed with it.
struct ScratchFolder {
  std::string path;
  ScratchFolder() {
    std::string pattern = (std::filesystem::temp_directory_path() / "firn_snowball_pair_XXXXXX").string();
    if (!mkdtemp(pattern.data())) throw std::runtime_error("cannot create a folder under " + pattern);
    path = pattern;
  }
  ~ScratchFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
};

double column(const sweep::MetricsHistory& h, const std::vector<double>& row, const char* name) {
  const int c = h.column_index(name);
  if (c < 0) throw std::runtime_error(std::string("snowball_pair: metrics.csv has no column ") + name);
  return row[std::size_t(c)];
}

}  // namespace

VerificationCase snowball_pair_energy_case(int level, const VerificationMethod& method,
                                           const VerificationOptions& options) {
  SceneOptions scene_options;
  scene_options.preview = level == 0;
  scene_options.overrides = {std::string("simulation.transfer=") + transfer_name(method.transfer),
                             std::string("simulation.shape=") + shape_name(method.shape),
                             std::string("simulation.precision=") + precision_name(method.precision)};
  const LoadedScene scene = load_scene(options.scene_folder + "/snowball_pair.toml", scene_options);
  const ScratchFolder out;
  RunOptions run;
  run.out_dir = out.path;
  run.backend = options.backend;
  run.threads = options.threads;
  const RunSummary summary = run_scene(scene, run);
  if (summary.status != "ok") throw StabilityError("snowball_pair: " + summary.status + ": " + summary.error);

  const sweep::MetricsHistory h = sweep::parse_metrics_csv(read_text_file(out.path + "/metrics.csv"));
  if (h.rows.empty()) throw std::runtime_error("snowball_pair: metrics.csv has no frames");
  const double e0 = column(h, h.rows.front(), "kinetic_energy") + column(h, h.rows.front(), "elastic_energy");
  if (options.log)
    for (const auto& row : h.rows)
      *options.log << "snowball_pair " << transfer_name(method.transfer) << " " << shape_name(method.shape) << " "
                   << precision_name(method.precision) << " level " << level << " t " << column(h, row, "time")
                   << " residual/initial " << column(h, row, "energy_residual") / e0 << " plastic_work/initial "
                   << column(h, row, "plastic_work") / e0 << "\n";
  VerificationCase c;
  c.dx = scene.spec.config.dx;
  c.particles_per_cell = scene.spec.per_axis();
  c.particles = summary.particles;
  c.steps = summary.steps;
  c.error = std::fabs(column(h, h.rows.back(), "energy_residual")) / e0;
  c.seconds = summary.step_seconds;
  return c;
}

}  // namespace firn::study
