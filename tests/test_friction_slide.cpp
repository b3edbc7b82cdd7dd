// scenes/friction_slide.toml, the thesis' friction experiment (section 4.1.2, Figure 4.2): rubber
// sliding on a rigid road under the velocity-dependent law (kernels/friction.hpp). Once the block
// has stopped bouncing on its contact, the road's force ratio |f_x| / |f_y| at every frame is the
// law's mu at the block's speed, at the thesis' lowest and highest speed (where mu differs by 44%).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "engine/scene/scene_run.hpp"
#include "kernels/friction.hpp"
#include "studies/sweep/metrics_history.hpp"

namespace firn {
namespace {

void expect_friction_follows_the_law(const std::string& speed) {
  const std::string dir = (std::filesystem::temp_directory_path() /
                           ("firn_friction_slide_" + std::to_string(getpid()) + "_" + speed)).string();
  SceneOptions o;
  o.overrides = {"bodies.0.velocity=[" + speed + ",0,0]", "simulation.end_time=20 ms"};
  RunOptions options;
  options.out_dir = dir;
  const RunSummary summary = run_scene(load_scene(std::string(FIRN_SOURCE_DIR) + "/scenes/friction_slide.toml", o), options);
  ASSERT_EQ(summary.status, "ok") << summary.error;
  std::stringstream csv;
  csv << std::ifstream(dir + "/metrics.csv").rdbuf();
  const sweep::MetricsHistory m = sweep::parse_metrics_csv(csv.str());
  const int t = m.column_index("time"), fx = m.column_index("road_fx"), fy = m.column_index("road_fy"),
            v = m.column_index("max_speed");
  ASSERT_GE(fx, 0);
  const Friction<double> law{FrictionLaw::velocity_dependent, 0.25};
  int checked = 0;
  for (const auto& row : m.rows) {
    if (row[t] < 0.01) continue;  // the block settles on its contact over the first 10 ms
    EXPECT_GT(row[fx], 0) << "t = " << row[t];  // the rubber drags the road along +x
    EXPECT_NEAR(row[fx] / -row[fy], law.coefficient(row[v]), 0.01 * law.coefficient(row[v])) << "t = " << row[t];
    ++checked;
  }
  EXPECT_GE(checked, 30);
  std::filesystem::remove_all(dir);
}

TEST(FrictionSlide, TheRoadsForceRatioIsTheLawsCoefficientAtTheBlocksSpeed) {
  expect_friction_follows_the_law("0.5");
  expect_friction_follows_the_law("4.47");
}

}  // namespace
}  // namespace firn
