#include "studies/sweep/sweep_plan.hpp"

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "engine/output/atomic_file.hpp"
#include "engine/scene/checkpoint.hpp"
#include "engine/scene/scene_lookup.hpp"
#include "engine/scene/scene_reader.hpp"
#include "engine/scene/units.hpp"
#include "studies/sweep/combinations.hpp"
#include "studies/sweep/metric_plot.hpp"
#include "studies/sweep/run_record.hpp"

namespace firn::sweep {

SweepPlan make_plan(const SweepOptions& o) {
  SweepPlan plan;
  for (const std::string& v : o.varies) {
    plan.keys.push_back(parse_vary(v));
    for (std::size_t k = 0; k + 1 < plan.keys.size(); ++k)
      if (plan.keys[k].key == plan.keys.back().key)
        throw std::invalid_argument("--vary " + plan.keys.back().key + " is given twice");
  }
  if (!o.at.empty())
    for (const std::string& t : split_value_list(o.at)) {
      try {
        plan.at_times.push_back(parse_quantity(t, Quantity::time));
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument("--at " + t + ": " + e.what());
      }
    }
  if (!o.checkpoint_every.empty()) checkpoint_interval(o.checkpoint_every);  // throws when it is not a time
  plan.plots_named = !o.plot.empty();
  plan.plots = plan.plots_named ? split_value_list(o.plot) : default_plotted_metrics;
  plan.combinations = cartesian_product(plan.keys);
  plan.scene = std::filesystem::absolute(find_scene(o.scene, o.shipped_scenes)).string();
  std::string name;
  for (const auto& values : plan.combinations) {
    std::vector<std::string> overrides = o.sets;
    for (const std::string& s : set_arguments(plan.keys, values)) overrides.push_back(s);
    name = load_scene(plan.scene, SceneOptions{overrides, o.preview}).spec.name;
  }
  plan.out = o.out.empty() ? "out/" + name + "_sweep" : o.out;
  return plan;
}

void save_sweep_args(const SweepOptions& o, const SweepPlan& plan) {
  std::string text = "scene=" + plan.scene + "\n";
  for (const std::string& v : o.varies) text += "vary=" + v + "\n";
  for (const std::string& v : o.sets) text += "set=" + v + "\n";
  if (!o.at.empty()) text += "at=" + o.at + "\n";
  if (!o.plot.empty()) text += "plot=" + o.plot + "\n";
  if (o.preview) text += "preview=true\n";
  if (!o.checkpoint_every.empty()) text += "checkpoint_every=" + o.checkpoint_every + "\n";
  if (o.render != "none") text += "render=" + o.render + "\n";
  std::filesystem::create_directories(plan.out);
  write_file_atomically(plan.out + "/sweep.args", text);
}

SweepOptions read_sweep_args(const std::string& dir) {
  std::ifstream in(dir + "/sweep.args");
  if (!in) throw std::invalid_argument(dir + ": no sweep.args there (not a sweep's output folder)");
  SweepOptions o;
  o.out = dir;
  for (std::string line; std::getline(in, line);) {
    const auto eq = line.find('=');
    const std::string name = line.substr(0, eq), value = eq == std::string::npos ? "" : line.substr(eq + 1);
    if (name == "scene") o.scene = value;
    else if (name == "vary") o.varies.push_back(value);
    else if (name == "set") o.sets.push_back(value);
    else if (name == "at") o.at = value;
    else if (name == "plot") o.plot = value;
    else if (name == "preview") o.preview = value == "true";
    else if (name == "checkpoint_every") o.checkpoint_every = value;
    else if (name == "render") o.render = value;
    else throw std::invalid_argument(dir + "/sweep.args: unknown line '" + line + "'");
  }
  return o;
}

std::string run_dir(const SweepPlan& plan, std::size_t index) {
  return plan.out + "/runs/" + run_name(index + 1, plan.combinations.size(), plan.combinations[index]);
}

std::vector<std::string> run_command(const SweepOptions& o, const SweepPlan& plan, std::size_t index,
                                     const std::string& self) {
  std::vector<std::string> argv = {self, "run", plan.scene, "--out", run_dir(plan, index)};
  std::vector<std::string> overrides = o.sets;
  for (const std::string& s : set_arguments(plan.keys, plan.combinations[index])) overrides.push_back(s);
  for (const std::string& s : overrides) argv.insert(argv.end(), {"--set", s});
  if (o.preview) argv.push_back("--preview");
  argv.insert(argv.end(), {"--backend", o.backend});
  if (!o.checkpoint_every.empty()) argv.insert(argv.end(), {"--checkpoint-every", o.checkpoint_every});
  if (o.render != "none") argv.insert(argv.end(), {"--render", o.render});
  return argv;
}

RunState run_state(const SweepPlan& plan, std::size_t index) {
  const std::string dir = run_dir(plan, index);
  if (const auto summary = file_text(dir + "/summary.json")) {
    const auto status = json_value(*summary, "status");
    if (status == "ok" || status == "unstable") return RunState::finished;
  }
  return std::filesystem::exists(checkpoint_path(dir)) ? RunState::resumable : RunState::to_run;
}

std::vector<std::string> resume_command(const SweepOptions& o, const SweepPlan& plan, std::size_t index,
                                        const std::string& self) {
  std::vector<std::string> argv = {self, "run", "--resume", run_dir(plan, index), "--backend", o.backend};
  if (!o.checkpoint_every.empty()) argv.insert(argv.end(), {"--checkpoint-every", o.checkpoint_every});
  if (o.render != "none") argv.insert(argv.end(), {"--render", o.render});
  return argv;
}

}  // namespace firn::sweep
