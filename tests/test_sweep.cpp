// firn sweep's engine-free parts (studies/sweep/): value lists, the Cartesian product, run names,
// metrics.csv read back, summary.json fields, sweep.csv assembly and the gnuplot files.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "studies/sweep/child_process.hpp"
#include "studies/sweep/combinations.hpp"
#include "studies/sweep/csv.hpp"
#include "studies/sweep/metric_plot.hpp"
#include "studies/sweep/metrics_history.hpp"
#include "studies/sweep/run_record.hpp"
#include "studies/sweep/sweep_table.hpp"
#include "studies/sweep/value_list.hpp"

namespace firn::sweep {
namespace {

using Strings = std::vector<std::string>;

TEST(SweepValueList, SplitsOnCommasOutsideBracketsAndQuotes) {
  EXPECT_EQ(split_value_list("angled_footstep,bowtie,six_rib"), (Strings{"angled_footstep", "bowtie", "six_rib"}));
  EXPECT_EQ(split_value_list("5 mph, 10 mph ,20 mph"), (Strings{"5 mph", "10 mph", "20 mph"}));
  EXPECT_EQ(split_value_list("[0,0,1],[0,0,2]"), (Strings{"[0,0,1]", "[0,0,2]"}));
  EXPECT_EQ(split_value_list("[[1,2],[3]],{a=1,b=2}"), (Strings{"[[1,2],[3]]", "{a=1,b=2}"}));
  EXPECT_EQ(split_value_list(R"("a,b",'c,d',"e\",f")"), (Strings{R"("a,b")", "'c,d'", R"("e\",f")"}));
  EXPECT_EQ(split_value_list("0.002"), (Strings{"0.002"}));
}

TEST(SweepValueList, RefusesEmptyValuesAndUnbalancedBrackets) {
  for (const char* bad : {"", "a,,b", "a,", ",a", "[0,0", "0,0]", "[0,0}", "\"a,b", "a, ,b"})
    EXPECT_THROW(split_value_list(bad), std::invalid_argument) << bad;
}

TEST(SweepValueList, ParsesVary) {
  const VariedKey v = parse_vary("bodies.0.velocity=[0,0,1],[0,0,2]");
  EXPECT_EQ(v.key, "bodies.0.velocity");
  EXPECT_EQ(v.values, (Strings{"[0,0,1]", "[0,0,2]"}));
  EXPECT_EQ(parse_vary("a=x=1,y").values, (Strings{"x=1", "y"}));  // only the first '=' ends the key
  for (const char* bad : {"novalues", "=1,2", "a=", "a=1,,2"})
    EXPECT_THROW(parse_vary(bad), std::invalid_argument) << bad;
  try {
    parse_vary("simulation.dx=0.1,");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("--vary simulation.dx=0.1,"), std::string::npos) << e.what();
  }
}

TEST(SweepCombinations, CartesianProductFirstKeySlowest) {
  const std::vector<VariedKey> keys = {{"a", {"1", "2"}}, {"b", {"x", "y", "z"}}};
  const auto c = cartesian_product(keys);
  ASSERT_EQ(c.size(), 6u);
  EXPECT_EQ(c[0], (Strings{"1", "x"}));
  EXPECT_EQ(c[1], (Strings{"1", "y"}));
  EXPECT_EQ(c[2], (Strings{"1", "z"}));
  EXPECT_EQ(c[3], (Strings{"2", "x"}));
  EXPECT_EQ(c[5], (Strings{"2", "z"}));
  EXPECT_EQ(set_arguments(keys, c[4]), (Strings{"a=2", "b=y"}));
  EXPECT_EQ(cartesian_product({{"a", {"1"}}, {"b", {"2"}}, {"c", {"3", "4"}}}).size(), 2u);
  EXPECT_EQ(cartesian_product({{"a", {"1", "2", "3"}}, {"b", {"1", "2"}}, {"c", {"3", "4", "5"}}}).size(), 18u);
}

TEST(SweepCombinations, RunNamesAreSafeAndNumbered) {
  EXPECT_EQ(run_name(3, 18, {"bowtie", "5 mph"}), "003_bowtie_5-mph");
  EXPECT_EQ(run_name(1, 2, {"[0,0,1]"}), "001_0-0-1");
  EXPECT_EQ(run_name(12, 1500, {"angled_footstep", "\"10 mph\""}), "0012_angled_footstep_10-mph");
  EXPECT_EQ(run_name(7, 9, {"../../etc", "a/b"}), "007_..-..-etc_a-b");
  EXPECT_EQ(run_name(2, 9, {"", "1e-3"}), "002_1e-3");
  const std::string long_name = run_name(1, 1, {std::string(100, 'x')});
  EXPECT_LE(long_name.size(), 4u + 40u);
  for (const std::string& name : {run_name(7, 9, {"../../etc", "a/b"}), run_name(1, 2, {"[0, 0, 1]"})})
    EXPECT_EQ(name.find_first_of("/ [],\"'"), std::string::npos) << name;
}

TEST(SweepCsv, QuotesFieldsAndSplitsThemBack) {
  EXPECT_EQ(csv_field("bowtie"), "bowtie");
  EXPECT_EQ(csv_field("[0,0,1]"), "\"[0,0,1]\"");
  EXPECT_EQ(csv_field("say \"hi\""), "\"say \"\"hi\"\"\"");
  const Strings fields = {"plain", "[0,0,1]", "say \"hi\", twice", ""};
  std::string line;
  for (std::size_t i = 0; i < fields.size(); ++i) line += (i ? "," : "") + csv_field(fields[i]);
  EXPECT_EQ(split_csv_line(line), fields);
  EXPECT_EQ(csv_number(0.1234567), "0.123457");
  EXPECT_EQ(csv_number(1e-12), "1e-12");
  EXPECT_EQ(csv_number(2000), "2000");
}

const std::string standard =
    "frame,step,time,dt,particles,kinetic_energy,elastic_energy,momentum_x,momentum_y,momentum_z,"
    "max_speed,min_J";
// Standard columns filled with a frame-dependent pattern, then the scene metrics given.
std::string metrics_csv(const std::string& scene_columns, const std::vector<std::pair<double, std::string>>& rows) {
  std::string text = standard + (scene_columns.empty() ? "" : "," + scene_columns) + "\n";
  int frame = 0;
  for (const auto& [time, scene_values] : rows) {
    text += std::to_string(frame) + "," + std::to_string(10 * frame) + "," + csv_number(time) +
            ",1e-4,100,1,2,0,0,0,3,1" + (scene_values.empty() ? "" : "," + scene_values) + "\n";
    ++frame;
  }
  return text;
}

TEST(SweepMetrics, ReadsSceneColumnsMeansAndValuesAtTimes) {
  const MetricsHistory h =
      parse_metrics_csv(metrics_csv("displaced,traction", {{0, "100,-5"}, {0.1, "2,1"}, {0.2, "4,"}, {0.3, "6,3"}}));
  EXPECT_EQ(h.columns.size(), 14u);
  EXPECT_EQ(h.scene_columns(), (Strings{"displaced", "traction"}));
  EXPECT_DOUBLE_EQ(*h.mean_after_first_frame("displaced"), 4.0);  // frame 0's 100 left out
  EXPECT_DOUBLE_EQ(*h.mean_after_first_frame("traction"), 2.0);   // the empty cell left out
  EXPECT_FALSE(h.mean_after_first_frame("accumulated"));
  EXPECT_DOUBLE_EQ(*h.value_at("displaced", 0.1), 2.0);
  EXPECT_DOUBLE_EQ(*h.value_at("displaced", 0.1 + 5e-10), 2.0);  // within 1e-9
  EXPECT_DOUBLE_EQ(*h.value_at("displaced", 0.15), 4.0);         // the first frame at or after
  EXPECT_DOUBLE_EQ(*h.value_at("displaced", 0), 100.0);
  EXPECT_FALSE(h.value_at("displaced", 0.31));  // never got there
  EXPECT_FALSE(h.value_at("traction", 0.2));    // empty cell
  EXPECT_TRUE(parse_metrics_csv(metrics_csv("", {{0, ""}})).scene_columns().empty());
  EXPECT_FALSE(parse_metrics_csv(metrics_csv("x", {{0, "1"}})).mean_after_first_frame("x"));  // frame 0 only
  EXPECT_THROW(parse_metrics_csv(""), std::runtime_error);
  EXPECT_THROW(parse_metrics_csv("a,b\n1,2\n"), std::runtime_error);
}

TEST(SweepSummary, ReadsFlatJsonValues) {
  const std::string json =
      "{\n  \"status\": \"unstable\",\n  \"error\": \"a \\\"status\\\": here\",\n  \"steps\": 42,\n"
      "  \"wall_seconds\": 1.5e-3,\n  \"state_hash\": null\n}\n";
  EXPECT_EQ(json_value(json, "status"), "unstable");
  EXPECT_EQ(json_value(json, "error"), "a \"status\": here");
  EXPECT_EQ(json_value(json, "steps"), "42");
  EXPECT_EQ(json_value(json, "wall_seconds"), "1.5e-3");
  EXPECT_FALSE(json_value(json, "state_hash"));
  EXPECT_FALSE(json_value(json, "particles"));
}

RunRecord record(Strings values, std::string status, std::optional<std::string> metrics) {
  RunRecord r;
  r.values = std::move(values);
  r.status = std::move(status);
  r.steps = 20, r.particles = 1000, r.wall_seconds = 1.25, r.particle_steps_per_second = 123456789;
  if (metrics) r.metrics = parse_metrics_csv(*metrics);
  return r;
}

std::vector<Strings> table(const std::string& csv) {
  std::vector<Strings> rows;
  std::size_t b = 0;
  for (std::size_t e; (e = csv.find('\n', b)) != std::string::npos; b = e + 1)
    rows.push_back(split_csv_line(csv.substr(b, e - b)));
  EXPECT_EQ(b, csv.size()) << "sweep.csv does not end with a line break";
  return rows;
}

TEST(SweepTable, ColumnsAreTheUnionOfMetricsInFirstSeenOrder) {
  const std::vector<RunRecord> runs = {
      record({"bowtie", "[0,0,1]"}, "ok",
             metrics_csv("displaced,traction", {{0, "0,0"}, {0.1, "1,10"}, {0.2, "3,20"}})),
      record({"six_rib", "[0,0,2]"}, "unstable", metrics_csv("accumulated,displaced", {{0, "0,0"}, {0.1, "7,5"}})),
      record({"angled", "[0,0,3]"}, "failed", std::nullopt),
  };
  const auto rows = table(sweep_csv({"tire.tread", "bodies.0.velocity"}, runs, {0.1, 0.2}));
  ASSERT_EQ(rows.size(), 4u);
  const Strings header = {"tire.tread",
                          "bodies.0.velocity",
                          "status",
                          "steps",
                          "particles",
                          "wall_seconds",
                          "particle_steps_per_second",
                          "mean_displaced",
                          "displaced@0.1",
                          "displaced@0.2",
                          "mean_traction",
                          "traction@0.1",
                          "traction@0.2",
                          "mean_accumulated",
                          "accumulated@0.1",
                          "accumulated@0.2"};
  EXPECT_EQ(rows[0], header);
  EXPECT_EQ(rows[1], (Strings{"bowtie", "[0,0,1]", "ok", "20", "1000", "1.25", "1.23457e+08", "2", "1", "3", "15", "10",
                              "20", "", "", ""}));
  EXPECT_EQ(rows[2], (Strings{"six_rib", "[0,0,2]", "unstable", "20", "1000", "1.25", "1.23457e+08", "5", "5", "", "",
                              "", "", "7", "7", ""}));
  EXPECT_EQ(rows[3], (Strings{"angled", "[0,0,3]", "failed", "20", "1000", "1.25", "1.23457e+08", "", "", "", "", "",
                              "", "", "", ""}));
  // No --at times: only the means; no scene metrics: only the run columns.
  EXPECT_EQ(table(sweep_csv({"k", "v"}, runs, {}))[0].size(), 7u + 3u);
  const auto plain = table(sweep_csv({"k"}, {record({"1"}, "ok", metrics_csv("", {{0, ""}, {0.1, ""}}))}, {0.1}));
  EXPECT_EQ(plain[0], (Strings{"k", "status", "steps", "particles", "wall_seconds", "particle_steps_per_second"}));
  EXPECT_EQ(plain[1].size(), plain[0].size());
}

TEST(SweepTable, MissingSummaryValuesAreEmpty) {
  RunRecord r;
  r.values = {"x"};
  const auto rows = table(sweep_csv({"k"}, {r}, {}));
  EXPECT_EQ(rows[1], (Strings{"x", "failed", "", "", "", ""}));
}

std::vector<RunRecord> plot_runs() {
  std::vector<RunRecord> runs;
  for (const char* snow : {"hard", "soft"})
    for (const char* speed : {"5 mph", "10 mph"})
      runs.push_back(
          record({snow, speed}, "ok", metrics_csv("traction,displaced", {{0, "0,0"}, {0.1, "1,2"}, {0.2, "2,4"}})));
  runs[3].metrics.reset();  // soft, 10 mph: no metrics (a failed run)
  return runs;
}

TEST(SweepPlot, OnePanelPerFirstKeyValueOneCurvePerOtherValues) {
  const std::vector<VariedKey> keys = {{"snow", {"hard", "soft", "none"}}, {"tire.speed", {"5 mph", "10 mph"}}};
  const auto plot = metric_plot("displaced", keys, plot_runs());
  ASSERT_TRUE(plot);
  const std::string& s = plot->script;
  EXPECT_NE(s.find("set multiplot layout 1,2"), std::string::npos) << s;  // "none" has no runs: no panel
  EXPECT_NE(s.find("set title 'snow = hard'"), std::string::npos) << s;
  EXPECT_NE(s.find("set title 'snow = soft'"), std::string::npos) << s;
  EXPECT_EQ(s.find("snow = none"), std::string::npos) << s;
  for (int i = 0; i < 3; ++i) EXPECT_NE(s.find("index " + std::to_string(i) + " "), std::string::npos) << s;
  EXPECT_EQ(s.find("index 3"), std::string::npos) << s;
  EXPECT_NE(s.find("title 'tire.speed = 5 mph'"), std::string::npos) << s;
  EXPECT_NE(s.find("title 'tire.speed = 10 mph'"), std::string::npos) << s;
  EXPECT_NE(s.find("set output 'displaced.png'"), std::string::npos) << s;
  EXPECT_NE(s.find("pngcairo"), std::string::npos) << s;
  // Three blocks separated by two blank lines, 3 points each.
  EXPECT_EQ(plot->data.find("\n\n\n\n"), std::string::npos);
  std::size_t separators = 0;
  for (auto at = plot->data.find("\n\n\n"); at != std::string::npos; at = plot->data.find("\n\n\n", at + 1))
    ++separators;
  EXPECT_EQ(separators, 2u) << plot->data;
  EXPECT_NE(plot->data.find("0.2 4\n"), std::string::npos) << plot->data;
  EXPECT_FALSE(metric_plot("accumulated", keys, plot_runs()));  // no run has it
  EXPECT_TRUE(metric_plot("traction", keys, plot_runs()));
  // One varied key: one panel, one curve per run, labelled with its value (the thesis' Figure 4.2).
  std::vector<RunRecord> one = plot_runs();
  for (auto& r : one) r.values.resize(1);
  const auto single = metric_plot("displaced", {{"snow", {"hard", "soft"}}}, one);
  ASSERT_TRUE(single);
  EXPECT_NE(single->script.find("set multiplot layout 1,1"), std::string::npos) << single->script;
  EXPECT_NE(single->script.find("index 2 using 1:2 with lines linewidth 2 linecolor 3 dashtype 1 title 'snow = soft'"),
            std::string::npos)
      << single->script;
  EXPECT_EQ(single->script.find("notitle"), std::string::npos) << single->script;
  const auto quoted =
      metric_plot("displaced", {{"snow", {"it's"}}}, {record({"it's"}, "ok", metrics_csv("displaced", {{0, "1"}}))});
  ASSERT_TRUE(quoted);
  EXPECT_NE(quoted->script.find("title 'snow = it''s'"), std::string::npos) << quoted->script;
}

// Without --plot, a sweep plots the thesis' Figures 5.5/5.6 quantities and traction.
TEST(SweepPlot, DefaultPlottedMetrics) {
  EXPECT_EQ(default_plotted_metrics, (Strings{"displaced", "accumulated", "traction"}));
}

bool on_path(const std::string& program) {
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "";
  for (std::size_t b = 0, e; b <= dirs.size(); b = e + 1) {
    e = dirs.find(':', b);
    if (e == std::string::npos) e = dirs.size();
    if (access((dirs.substr(b, e - b) + "/" + program).c_str(), X_OK) == 0) return true;
  }
  return false;
}

std::filesystem::path scratch(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("firn_test_sweep_" + std::to_string(getpid())) / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// The script gnuplot really runs: a PNG comes out (skipped where gnuplot-nox is not installed).
TEST(SweepPlot, GnuplotDrawsThePng) {
  if (!on_path("gnuplot")) GTEST_SKIP() << "gnuplot is not installed (Debian package gnuplot-nox)";
  const auto dir = scratch("plot");
  const auto plot =
      metric_plot("displaced", {{"snow", {"hard", "soft"}}, {"tire.speed", {"5 mph", "10 mph"}}}, plot_runs());
  ASSERT_TRUE(plot);
  std::ofstream(dir / "displaced.dat") << plot->data;
  std::ofstream(dir / "displaced.gp") << plot->script;
  const int status =
      wait_child(start_child({{"gnuplot", "displaced.gp"}, (dir / "gnuplot.log").string(), dir.string(), true}));
  std::ifstream log(dir / "gnuplot.log");
  const std::string log_text((std::istreambuf_iterator<char>(log)), std::istreambuf_iterator<char>());
  EXPECT_EQ(status, 0) << log_text;
  EXPECT_TRUE(log_text.empty()) << log_text;  // no warnings (e.g. an empty data block)
  std::ifstream png(dir / "displaced.png", std::ios::binary);
  char magic[8] = {};
  png.read(magic, 8);
  EXPECT_EQ(std::string(magic + 1, 3), "PNG");
  EXPECT_GT(std::filesystem::file_size(dir / "displaced.png"), 5000u);
  std::filesystem::remove_all(dir.parent_path());
}

TEST(SweepChildProcess, LogsOutputAndReportsExitStatus) {
  const auto dir = scratch("child");
  const std::string log = (dir / "log.txt").string();
  EXPECT_EQ(wait_child(start_child({{"/bin/sh", "-c", "echo out; echo err >&2; exit 3"}, log, "", false})), 3);
  std::ifstream in(log);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text, "out\nerr\n");
  EXPECT_EQ(wait_child(start_child({{"/bin/pwd", "-P"}, log, dir.string(), false})), 0);
  std::ifstream pwd(log);
  std::string cwd;
  std::getline(pwd, cwd);
  EXPECT_EQ(cwd, std::filesystem::canonical(dir).string());
  EXPECT_EQ(wait_child(start_child({{"/bin/sh", "-c", "kill -TERM $$"}, log, "", false})), 128 + 15);
  EXPECT_EQ(wait_child(start_child({{"firn-no-such-program"}, log, "", true})), 127);
  EXPECT_EQ(wait_child(start_child({{"/no/such/program"}, log, "", false})), 127);
  EXPECT_THROW(start_child({{"/bin/true"}, (dir / "no" / "such" / "log.txt").string(), "", false}), std::runtime_error);
  std::filesystem::remove_all(dir.parent_path());
}

}  // namespace
}  // namespace firn::sweep
