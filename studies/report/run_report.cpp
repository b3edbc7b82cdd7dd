#include "studies/report/run_report.hpp"

#include <cmath>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <vector>

#include "engine/output/atomic_file.hpp"
#include "studies/report/html_writer.hpp"
#include "studies/report/numbered_files.hpp"
#include "studies/report/scene_parameters.hpp"
#include "studies/sweep/gnuplot.hpp"
#include "studies/sweep/metric_plot.hpp"
#include "studies/sweep/run_record.hpp"

namespace firn::report {
namespace {

// summary.json's keys (engine/output/run_summary.hpp), in the order a reader wants them.
const char* const kSummaryKeys[] = {"status", "error", "steps", "particles", "wall_seconds", "step_seconds",
                                    "particle_steps_per_second", "threads", "openmp_wait", "backend", "precision",
                                    "peak_memory_mb"};

bool exists(const std::string& path) { return std::filesystem::exists(path); }

std::string status_html(const std::string& summary) {
  HtmlTable t;
  t.header = {"summary.json", "value"};
  for (const char* key : kSummaryKeys)
    if (const auto value = sweep::json_value(summary, key)) t.rows.push_back({key, *value});
  return html_table(t);
}

// Whether the column is 0 (or empty) at every frame: a flat line not worth a plot (the plastic work
// of an elastic body, the collider work without colliders).
bool zero_throughout(const sweep::MetricsHistory& metrics, const std::string& column) {
  const int c = metrics.column_index(column);
  for (const auto& row : metrics.rows)
    if (c >= 0 && row[std::size_t(c)] != 0 && !std::isnan(row[std::size_t(c)])) return false;
  return true;
}

// Draws DIR/plots/METRIC.png for the standard metrics and the scene's own, but those zero
// throughout, which it names; returns the markup.
std::string metric_figures(const std::string& dir, const sweep::MetricsHistory& metrics) {
  std::vector<std::string> columns(std::begin(run_plotted_standard_metrics), std::end(run_plotted_standard_metrics));
  for (const std::string& c : metrics.scene_columns()) columns.push_back(c);
  sweep::RunRecord run;
  run.metrics = metrics;
  std::vector<std::string> figures;
  std::string zero;
  for (const std::string& metric : columns) {
    if (zero_throughout(metrics, metric)) {
      zero += (zero.empty() ? "" : ", ") + metric;
      continue;
    }
    const auto plot = sweep::metric_plot(metric, {}, {run});
    if (!plot) continue;
    const sweep::PlotStatus status = sweep::draw_plot_or_warn("firn report", dir + "/plots", metric, *plot);
    if (status == sweep::PlotStatus::no_gnuplot) break;
    if (status == sweep::PlotStatus::drawn) figures.push_back(html_figure("plots/" + metric + ".png", metric));
  }
  std::string html = figures.empty() ? html_paragraph("No plots (gnuplot is missing or failed; see firn's messages).")
                                     : html_gallery(figures, 380);
  if (!zero.empty()) html += html_paragraph("0 at every frame: " + zero + ".");
  return html;
}

// Figures of `picked`, each captioned "WHAT N" with its frame number.
std::vector<std::string> numbered_figures(const std::vector<std::string>& picked, const std::string& what) {
  std::vector<std::string> figures;
  for (const std::string& name : picked) figures.push_back(html_figure(name, what + " " + std::to_string(frame_number(name))));
  return figures;
}

}  // namespace

std::string folder_name(const std::string& dir) {
  std::filesystem::path p = std::filesystem::absolute(dir).lexically_normal();
  if (p.filename().empty()) p = p.parent_path();  // "out/run/" names "run"
  return p.filename().string();
}

std::string write_run_report(const std::string& dir) {
  const std::optional<std::string> summary = sweep::file_text(dir + "/summary.json");
  const std::optional<std::string> scene = sweep::file_text(dir + "/scene.resolved.toml");
  if (!summary && !scene)
    throw std::invalid_argument(dir + ": not a run's output folder (no summary.json or scene.resolved.toml)");
  std::string body;
  body += html_heading(2, "Status and timings");
  body += summary ? status_html(*summary) : html_paragraph("No summary.json: the run has not finished.");

  body += html_heading(2, "Scene");
  if (scene) body += scene_parameters_html(*scene);
  body += "<p>" + html_link("scene.resolved.toml", "scene.resolved.toml") +
          ": every value used, defaults filled in (firn run scene.resolved.toml repeats the run)</p>\n";

  body += html_heading(2, "Metrics");
  if (const auto text = sweep::file_text(dir + "/metrics.csv")) {
    try {
      body += metric_figures(dir, sweep::parse_metrics_csv(*text));
    } catch (const std::runtime_error& e) {
      body += html_paragraph(std::string("metrics.csv: ") + e.what());
    }
    body += "<p>" + html_link("metrics.csv", "metrics.csv") + ": one row per frame</p>\n";
  } else {
    body += html_paragraph("No metrics.csv.");
  }

  const std::vector<std::string> footprints = numbered_files(dir, "footprint", ".png");
  if (!footprints.empty()) {
    body += html_heading(2, "Footprint");
    body += html_gallery(numbered_figures(evenly_spaced(footprints, report_footprints), "footprint, frame"), 380);
    body += "<p>" + std::to_string(footprints.size()) + " maps in " + html_link("footprint/", "footprint/") +
            " (PNG and the pressures in Pa as CSV)</p>\n";
  }

  const std::vector<std::string> frames = numbered_files(dir, "frames", ".png");
  if (!frames.empty()) {
    body += html_heading(2, "Frames");
    body += html_gallery(numbered_figures(evenly_spaced(frames, report_frames), "frame"), 380);
    body += "<p>" + std::to_string(frames.size()) + " frames in " + html_link("frames/", "frames/") + "</p>\n";
  }
  if (exists(dir + "/video.mp4")) body += html_heading(2, "Video") + html_video("video.mp4");

  const std::string path = dir + "/report.html";
  write_file_atomically(path, html_page("firn run: " + folder_name(dir), body));
  return path;
}

}  // namespace firn::report
