#include "studies/stability/stability_study.hpp"

#include <chrono>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "engine/backend_kind.hpp"
#include "engine/output/atomic_file.hpp"
#include "engine/scene/scene_lookup.hpp"
#include "engine/scene/scene_reader.hpp"
#include "studies/stability/stability_cfl.hpp"
#include "studies/stability/stability_impact.hpp"
#include "studies/stability/stability_long_run.hpp"
#include "studies/stability/stability_random_runs.hpp"
#include "studies/stability/stability_report.hpp"
#include "studies/stability/stability_scenes.hpp"
#include "studies/sweep/child_process.hpp"
#include "studies/sweep/csv.hpp"
#include "studies/sweep/gnuplot.hpp"

namespace firn::study {
namespace {

using sweep::csv_number;
using Clock = std::chrono::steady_clock;

// The thesis' scenes whose CFL limit the study measures, at shortened end times (s); snowball_wall
// also gives the impact speed.
struct ThesisScene {
  const char* file;
  double end, quick_end;
};
const ThesisScene kThesisScenes[] = {{"snowball_wall", 0.01, 0.004},
                                     {"snowball_pair", 0.01, 0.004},
                                     {"snow_bar", 0.1, 0.02},
                                     {"tire_on_snow", 0.1, 0.005}};

class StabilityStudy {
 public:
  explicit StabilityStudy(const StabilityStudyOptions& o)
      : o_(o), quick_(o.study.quick), dir_(o.study.out), report_(o.study.out), start_(Clock::now()) {
    probe_.backend = backend_named(o.study.backend);
    probe_.threads = o.study.threads;
  }

  int run() {
    make_directories(dir_);
    cfl_per_material();
    cfl_per_thesis_scene();
    impact_speed();
    incompressibility();
    long_run_check();
    const int failures = random_scenes();
    plot_cfl();
    report_.write_markdown(notes());
    progress("done; " + dir_ + "/stability.csv, " + dir_ + "/stability.md");
    return failures > 0 ? 1 : 0;
  }

 private:
  void progress(const std::string& what) const {
    if (o_.progress) o_.progress("[" + sweep::formatted("%.1f", seconds_since(start_)) + " s] " + what);
  }

  // The bisection bracket for CFL numbers: from 0.1 to 3 (beyond the scene files' limit of 1, which
  // the study lifts to see where the limit really is).
  BisectionSettings cfl_bracket() const { return {0.1, 3.0, quick_ ? 0.1 : 0.02, false}; }

  static std::string bracket_text(const BisectionSettings& b) {
    return "bracket [" + csv_number(b.lo) + ", " + csv_number(b.hi) + "], tolerance " + csv_number(b.tolerance) +
           (b.geometric ? " (ratio)" : "");
  }

  // The bisection's answer as a headline row, with the first failure's reason in the detail.
  void bisection_row(const std::string& check, const std::string& subject, const std::string& what,
                     const std::string& unit, const BisectionSettings& bracket, const BisectionResult& r,
                     const std::string& first_failure, double seconds) {
    StabilityRow row{check, subject, what, r.largest_ok, unit, "result", "", seconds, true};
    if (!r.largest_ok) row.detail = "fails at the bracket's low end " + csv_number(bracket.lo) + "; ";
    else if (!r.smallest_fail) row.detail = "runs at the bracket's high end: the limit is above " + csv_number(bracket.hi) + "; ";
    else row.detail = "fails at " + csv_number(*r.smallest_fail) + "; ";
    row.detail += bracket_text(bracket) + "; " + std::to_string(r.trials.size()) + " runs";
    if (!first_failure.empty()) row.detail += "; failure: " + first_failure;
    report_.add(row);
    cfl_results_.push_back({subject, r});
  }

  // One bisection trial as a row; keeps the reason of the failure nearest the answer.
  void trial_row(const std::string& check, const std::string& subject, const std::string& setting, double value,
                 const std::string& unit, const ProbeResult& r, std::string& failure) {
    std::string detail = r.detail;
    if (r.ok()) detail = "min J " + csv_number(r.min_J) + ", energy growth " + csv_number(r.max_growth) +
                         (r.detail.empty() ? "" : "; " + r.detail);
    else failure = probe_outcome_text(r.outcome) + std::string(": ") + r.detail;
    report_.add({check, subject, setting + "=" + csv_number(value), value, unit, probe_outcome_text(r.outcome),
                 detail + "; " + std::to_string(r.steps) + " steps, " + std::to_string(r.particles) + " particles",
                 r.seconds, false});
  }

  void cfl_per_material() {
    const double end = quick_ ? 0.008 : 0.02;
    for (const StudyMaterial& m : thesis_materials()) {
      const auto t0 = Clock::now();
      const LoadedScene scene = write_and_load_scene(dir_, "ball_wall_" + m.name, ball_wall_scene(m, end));
      std::string failure;
      const BisectionResult r = largest_stable_cfl(scene.spec, cfl_bracket(), probe_, [&](double cfl, const ProbeResult& p) {
        trial_row("cfl", m.name, "cfl", cfl, "", p, failure);
      });
      bisection_row("cfl", m.name + " (ball into a wall, " + sweep::formatted("%.0f", end * 1e3) + " ms)", "largest stable cfl", "",
                    cfl_bracket(), r, failure, seconds_since(t0));
      progress("cfl " + m.name + ": " + (r.largest_ok ? csv_number(*r.largest_ok) : std::string("none")));
    }
  }

  void cfl_per_thesis_scene() {
    for (const ThesisScene& t : kThesisScenes) {
      const auto t0 = Clock::now();
      const double end = quick_ ? t.quick_end : t.end;
      const LoadedScene scene = load_scene(thesis_scene(o_, t.file),
                                           SceneOptions{{"simulation.end_time=" + csv_number(end)}, true});
      std::string failure;
      const BisectionResult r = largest_stable_cfl(scene.spec, cfl_bracket(), probe_, [&](double cfl, const ProbeResult& p) {
        trial_row("cfl", t.file, "cfl", cfl, "", p, failure);
      });
      bisection_row("cfl", std::string(t.file) + " (--preview, " + sweep::formatted("%.0f", end * 1e3) + " ms)", "largest stable cfl", "",
                    cfl_bracket(), r, failure, seconds_since(t0));
      progress(std::string("cfl ") + t.file + ": " + (r.largest_ok ? csv_number(*r.largest_ok) : std::string("none")));
    }
  }

  void impact_speed() {
    const auto t0 = Clock::now();
    const LoadedScene scene = load_scene(thesis_scene(o_, "snowball_wall"), SceneOptions{{}, true});
    const BisectionSettings bracket{2, 512, quick_ ? 0.15 : 0.02, true};
    std::string failure;
    const BisectionResult r = highest_survived_speed(scene.spec, bracket, probe_, [&](double v, const ProbeResult& p) {
      trial_row("impact_speed", "snowball_wall", "speed", v, "m/s", p, failure);
    });
    StabilityRow row{"impact_speed", "snowball_wall (--preview, cfl 0.4, 10 ms)", "highest speed survived", r.largest_ok,
                     "m/s", "result", "", seconds_since(t0), true};
    row.detail = (r.smallest_fail ? "fails at " + csv_number(*r.smallest_fail) + " m/s; "
                                  : "survives the bracket's high end; ") +
                 bracket_text(bracket) + "; " + std::to_string(r.trials.size()) + " runs" +
                 (failure.empty() ? "" : "; failure: " + failure);
    report_.add(row);
    progress("impact speed: " + (r.largest_ok ? csv_number(*r.largest_ok) + " m/s" : std::string("none")));
  }

  void incompressibility() {
    const double end = quick_ ? 0.002 : 0.004;
    std::string data = "# nu mooney_rivlin_checkerboard neo_hookean_checkerboard\n";
    std::vector<std::vector<double>> table;
    for (const double nu : {0.3, 0.45, 0.49, 0.499}) {  // 0.3: a compressible reference
      std::vector<double> line = {nu};
      for (const char* model : {"mooney_rivlin", "neo_hookean"}) {
        const StudyMaterial m = rubber(model, nu);
        const LoadedScene scene = write_and_load_scene(dir_, "squeezed_block_" + m.name, squeezed_block_scene(m, end));
        ProbeSettings probe = probe_;
        probe.measure_checkerboard = true;
        const ProbeResult r = probe_scene(scene.spec, probe);
        const ProbeSample& c = r.last;
        const std::string what = std::string(model) + " nu=" + csv_number(nu);
        report_.add({"incompressibility", what, "min J", r.min_J, "", probe_outcome_text(r.outcome), r.detail, r.seconds,
                     false});
        report_.add({"incompressibility", what, "pressure checkerboard", c.checkerboard, "",
                     probe_outcome_text(r.outcome),
                     "at the end (t = " + csv_number(c.time) + " s, mean pressure " + csv_number(c.mean_pressure) +
                         " Pa); min J " + csv_number(r.min_J) + ", " + std::to_string(r.steps) + " steps" +
                         (r.ok() ? "" : "; " + r.detail),
                     r.seconds, true});
        line.push_back(c.checkerboard);
        progress("incompressibility " + what + ": " + probe_outcome_text(r.outcome) + ", checkerboard " +
                 csv_number(c.checkerboard));
      }
      data += csv_number(line[0]) + " " + csv_number(line[1]) + " " + csv_number(line[2]) + "\n";
    }
    plot("incompressibility", data,
         "set xlabel 'Poisson ratio nu'\nset ylabel 'pressure checkerboard indicator'\nset logscale y\nset key top left\n"
         "set title 'Rubber block under its own weight at 2000 m/s^2 (E = 1e7 Pa): RMS(p - neighbour mean) / |mean p|'\n"
         "plot 'incompressibility.dat' using 1:2 with linespoints title 'Mooney-Rivlin', "
         "'' using 1:3 with linespoints title 'neo-Hookean'\n");
  }

  void long_run_check() {
    const long steps = quick_ ? 10000 : 100000;
    // An end time beyond the steps: dt is about 0.4 * 4 mm / 20 m/s = 8e-5 s.
    const LoadedScene scene = write_and_load_scene(dir_, "resting_block", resting_block_scene(1e3));
    const LongRunResult r = long_run(scene.spec, steps, probe_);
    const std::string subject = "hard snow block at rest (" + std::to_string(steps) + " steps)";
    const std::string outcome = probe_outcome_text(r.run.outcome);
    const std::string when = std::to_string(r.run.steps) + " steps, " + csv_number(r.run.time) + " s simulated";
    report_.add({"long_run", subject, "energy drift", r.energy_drift, "", outcome,
                 "(E_end - E_0) / E_0, E = kinetic + elastic + potential from the domain floor 12 mm below the block; " +
                     when + (r.run.ok() ? "" : "; " + r.run.detail),
                 r.run.seconds, true});
    report_.add({"long_run", subject, "creep rate", r.creep_rate, "m/s", outcome,
                 "settling speed of the top surface, least-squares over the second half; " + when, 0, true});
    report_.add({"long_run", subject, "settlement", r.settlement, "m", outcome,
                 "top surface at step 0 minus at the end (24 mm block); " + when, 0, true});
    std::string data = "# time energy_ratio top_height_mm\n";
    const double e0 = r.run.first.total();
    for (const ProbeSample& s : r.history)
      data += csv_number(s.time) + " " + csv_number(s.total() / e0) + " " + csv_number(s.top_height * 1e3) + "\n";
    plot("long_run", data,
         "set xlabel 'time (s)'\nset ylabel 'total energy / initial'\nset y2label 'top surface height (mm)'\n"
         "set ytics nomirror\nset y2tics\nset key bottom left\n"
         "set title 'Hard snow block at rest on a floor: energy and creep'\n"
         "plot 'long_run.dat' using 1:2 with lines title 'energy (kinetic + elastic + potential)', "
         "'' using 1:3 axes x1y2 with lines title 'top surface height'\n");
    progress("long run: drift " + csv_number(r.energy_drift) + ", creep " + csv_number(r.creep_rate) + " m/s");
  }

  int random_scenes() {
    RandomRunSettings s;
    s.firn = sweep::self_executable();
    s.dir = dir_ + "/random";
    s.seed = o_.seed;
    s.count = o_.random > 0 ? o_.random : quick_ ? 20 : 200;
    s.jobs = 2;
    s.backend = o_.study.backend;
    std::filesystem::remove_all(s.dir);  // only this run's failures stay
    const auto t0 = Clock::now();
    int done = 0, failures = 0, finished = 0, guard = 0;
    run_random_scenes(s, [&](const RandomRunResult& r) {
      ++done;
      failures += r.failed() ? 1 : 0;
      finished += r.outcome == "finished" ? 1 : 0;
      guard += r.outcome == "guard_stop" ? 1 : 0;
      report_.add({"random_scene", "seed " + std::to_string(s.seed) + " scene " + std::to_string(r.index),
                   r.scene + " (~" + std::to_string(r.particles_estimate) + " particles)", double(r.exit_status),
                   "exit status", r.outcome, r.detail, r.seconds, false});
      if (r.failed() || done % 20 == 0 || done == s.count)
        progress("random scenes " + std::to_string(done) + "/" + std::to_string(s.count) + ": scene " +
                 std::to_string(r.index) + " " + r.outcome + (r.failed() ? " (" + r.detail + ")" : ""));
    });
    report_.add({"random_scene", "seed " + std::to_string(s.seed) + ", " + std::to_string(s.count) + " scenes",
                 "failures (crash, bad input or NaN)", double(failures), "", failures ? "fail" : "result",
                 std::to_string(finished) + " finished, " + std::to_string(guard) + " stopped by the guard, " +
                     std::to_string(failures) + " failed; 2 at a time on 1 thread each; failing scenes kept in " + s.dir,
                 seconds_since(t0), true});
    return failures;
  }

  void plot_cfl() {
    std::string data = "# index largest_ok smallest_fail label\n";
    for (std::size_t i = 0; i < cfl_results_.size(); ++i) {
      const BisectionResult& r = cfl_results_[i].second;
      std::string label = cfl_results_[i].first.substr(0, cfl_results_[i].first.find(' '));
      data += std::to_string(i) + " " + (r.largest_ok ? csv_number(*r.largest_ok) : "0") + " " +
              (r.smallest_fail ? csv_number(*r.smallest_fail) : "NaN") + " " + sweep::csv_field(label) + "\n";
    }
    plot("cfl", data,
         "set ylabel 'CFL number'\nset xtics rotate by -30\nset key top right\nset yrange [0:*]\n"
         "set title 'Largest stable CFL (bisection): dt = cfl dx / max(c_p + |v_p|)'\nset style fill solid 0.5\n"
         "set boxwidth 0.6\n"
         "plot 'cfl.dat' using 1:2:xtic(4) with boxes title 'largest that ran to the end', "
         "'' using 1:3 with points pt 7 title 'smallest that failed'\n");
  }

  void plot(const std::string& name, const std::string& data, const std::string& script) {
    sweep::draw_plot_or_warn("firn study stability", dir_, name,
                             {data, sweep::gnuplot_png_output(name + ".png", 900, 560) + script});
  }

  std::string notes() const {
    return "## How each figure is measured\n\n"
           "- **Runs to the end**: no stability-guard stop (NaN/Inf, J <= 0, a particle moving more than dx in a "
           "step), no non-finite energy, and no energy blow-up: total energy E = kinetic + elastic + gravitational "
           "potential (from the domain's lowest corner) never exceeds 1.01 E(0). MLS-MPM/APIC with plasticity and "
           "friction only dissipates (Jiang et al. 2015), so energy that neither gravity nor the initial motion "
           "could supply is an instability the guard missed. Scenes where a moving collider, the tire, a conveyor or a "
           "load does work are not energy-tested.\n"
           "- **CFL**: bisection on cfl in dt = cfl dx / max_p(c_p + |v_p|) with dt_max lifted to 1 s; " +
           bracket_text(cfl_bracket()) + ". Materials: a 20 mm ball (dx 4 mm, 8 per cell) thrown at 5 m/s into a "
           "plane wall under gravity; thesis scenes at --preview with shortened end times.\n"
           "- **Impact speed**: snowball_wall at --preview, every layer at the same speed; geometric bisection, "
           "survives = no guard stop. The CFL step includes |v|, so a particle moving at the speed of the previous "
           "step covers at most cfl dx |v| / (c + |v|) < cfl dx: the guard's too_fast test can only fire when a "
           "particle speeds up within one step by more than 1/cfl; what limits the speed is the compression at the "
           "wall (J <= 0) or a particle flung faster than the step allows.\n"
           "- **Pressure checkerboard**: RMS over particles of (p_i - mean pressure of the other particles within "
           "dx) divided by |mean pressure|, at the end of a 40 x 20 x 40 mm block squeezed on a sticky floor by its own "
           "weight under 2000 m/s^2, a smooth pressure from 0 to 37 kPa (studies/stability/stability_checkerboard.hpp).\n"
           "- **Long run**: energy drift (E_end - E_0) / E_0 and creep (settling speed of the top layer, "
           "least-squares over the second half); plot long_run.png.\n"
           "- **Random scenes**: each a `firn run` child with 1 thread; finished or guard_stop pass, crash, bad_input "
           "or a NaN/Inf in metrics.csv or a .vtp frame fail.\n\n"
           "Every trial run is a row of stability.csv; the study's own scenes are in scenes/.\n";
  }

  static double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

  const StabilityStudyOptions& o_;
  const bool quick_;
  const std::string dir_;
  StabilityReport report_;
  ProbeSettings probe_;
  const Clock::time_point start_;
  std::vector<std::pair<std::string, BisectionResult>> cfl_results_;
};

}  // namespace

std::string thesis_scene(const StabilityStudyOptions& o, const std::string& name) {
  return o.scenes.empty() ? find_scene(name, o.shipped_scenes) : o.scenes + "/" + name + ".toml";
}

void check_thesis_scenes(const StabilityStudyOptions& o) {
  for (const ThesisScene& t : kThesisScenes)
    if (!std::filesystem::is_regular_file(thesis_scene(o, t.file)))
      throw SceneError(thesis_scene(o, t.file) + " not found (--scenes names a folder holding " + t.file + ".toml)");
}

int run_stability_study(const StabilityStudyOptions& o) { return StabilityStudy(o).run(); }

}  // namespace firn::study
