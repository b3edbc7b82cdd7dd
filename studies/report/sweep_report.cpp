#include "studies/report/sweep_report.hpp"

#include <algorithm>
#include <filesystem>
#include <map>
#include <vector>

#include "engine/output/atomic_file.hpp"
#include "studies/report/html_writer.hpp"
#include "studies/report/numbered_files.hpp"
#include "studies/report/pivot_table.hpp"
#include "studies/report/run_report.hpp"
#include "studies/sweep/run_record.hpp"
#include "studies/sweep/sweep_collect.hpp"

namespace firn::report {
namespace {

// What the thesis called the figure a metric's plot reproduces.
const std::map<std::string, std::string> kThesisFigures = {
    {"displaced", " (the thesis' Figure 5.5)"}, {"accumulated", " (the thesis' Figure 5.6)"}};

// Run `index`'s folder relative to the sweep's.
std::string relative_run(const sweep::SweepPlan& plan, std::size_t index) {
  return "runs/" + std::filesystem::path(sweep::run_dir(plan, index)).filename().string();
}

// sweep.csv with a first column linking each row to its run's page.
std::string runs_table(const sweep::SweepPlan& plan, const CsvTable& csv) {
  const std::size_t keys = varied_key_columns(csv);
  HtmlTable t;
  t.caption = "sweep.csv: one row per finished run";
  t.header = csv.header;
  t.header.insert(t.header.begin(), "run");
  t.first_cells_html = true;
  for (const auto& row : csv.rows) {
    const std::vector<std::string> values(row.begin(), row.begin() + std::ptrdiff_t(std::min(keys, row.size())));
    const auto at = std::find(plan.combinations.begin(), plan.combinations.end(), values);
    std::string link;
    if (at != plan.combinations.end()) {
      const std::size_t index = std::size_t(at - plan.combinations.begin());
      link = html_link(relative_run(plan, index) + "/report.html", std::to_string(index + 1));
    }
    t.rows.push_back(row);
    t.rows.back().insert(t.rows.back().begin(), link);
  }
  return html_table(t);
}

}  // namespace

std::string write_sweep_report(const std::string& dir, const std::string& shipped_scenes,
                               const sweep::SweepReport& report) {
  const sweep::SweepPlan plan = sweep::saved_plan(dir, "", shipped_scenes);
  const sweep::CollectedSweep collected = sweep::collect_sweep(plan, report);
  for (std::size_t i = 0; i < plan.combinations.size(); ++i)
    if (std::filesystem::exists(sweep::run_dir(plan, i) + "/summary.json")) write_run_report(sweep::run_dir(plan, i));
  const CsvTable csv = parse_csv(read_text_file(dir + "/sweep.csv"));

  std::string body;
  std::string varied;
  for (const sweep::VariedKey& k : plan.keys) {
    varied += (varied.empty() ? "" : "; ") + k.key + " = ";
    for (std::size_t v = 0; v < k.values.size(); ++v) varied += (v ? ", " : "") + k.values[v];
  }
  body += html_paragraph("Scene " + plan.scene + ", varied: " + varied + ". " + std::to_string(collected.finished) +
                         " of " + std::to_string(collected.total) + " runs finished" +
                         (collected.missing.empty() ? "" : " (not yet: run " + collected.missing + ")") +
                         (collected.all_ok ? "" : "; not every finished run is ok") + ".");

  const std::vector<std::string> sheets = numbered_files(dir, "contact_sheets", ".png");
  if (!sheets.empty()) {
    body += html_heading(2, "Contact sheets");
    std::vector<std::string> figures;
    for (const std::string& sheet : sheets)
      figures.push_back(html_figure(sheet, "frame " + std::to_string(frame_number(sheet)) + " of every run"));
    body += html_gallery(figures, 1150);
  }

  body += html_heading(2, "Metrics against time");
  std::vector<std::string> figures;
  for (const std::string& metric : plan.plots)
    if (std::filesystem::exists(dir + "/plots/" + metric + ".png")) {
      const auto figure = kThesisFigures.find(metric);
      figures.push_back(html_figure("plots/" + metric + ".png",
                                    metric + (figure == kThesisFigures.end() ? "" : figure->second)));
    }
  body += figures.empty() ? html_paragraph("No plots (no run has these metrics, or gnuplot is missing).")
                          : html_gallery(figures, 1150);

  if (std::filesystem::exists(dir + "/plots/footprints.png"))
    body += html_heading(2, "Footprints (the thesis' Figure 5.7)") +
            html_gallery({html_figure("plots/footprints.png", "each run's last footprint, on one colour scale")}, 1150);

  std::string pivots;
  for (const std::string& metric : plan.plots) {
    const HtmlTable pivot = pivot_table(csv, metric);
    if (!pivot.rows.empty()) pivots += html_table(pivot);
  }
  if (!pivots.empty())
    body += html_heading(2, "Metrics by varied value (the thesis' Table 5.1)") +
            html_paragraph("mean_C: the mean over the frames after the first; C@T: the value at time T (firn sweep --at).") +
            pivots;

  body += html_heading(2, "Runs") + runs_table(plan, csv);
  body += "<p>" + html_link("sweep.csv", "sweep.csv") + ", " + html_link("sweep.args", "sweep.args") +
          " (the sweep's options), each run's folder under " + html_link("runs/", "runs/") + "</p>\n";

  const std::string path = dir + "/report.html";
  write_file_atomically(path, html_page("firn sweep: " + folder_name(dir), body));
  return path;
}

}  // namespace firn::report
