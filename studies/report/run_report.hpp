// firn report on a run's output folder (issue 18 item 5; DESIGN.md section 5): DIR/report.html with
// the run's status and timings (summary.json), its scene's key parameters (scene.resolved.toml),
// its metric histories as gnuplot plots (DIR/plots/METRIC.png), a few footprint maps, a strip of
// frames and the video, each linked to its file beside the page.
#pragma once

#include <cstddef>
#include <string>

namespace firn::report {

// The metrics.csv columns a run's report plots, besides the scene's own: the energies and the
// checks of a sound run.
inline constexpr const char* run_plotted_standard_metrics[] = {"kinetic_energy", "elastic_energy", "max_speed",
                                                               "min_J"};

// Frames and footprint maps the page shows; the others are a link away.
inline constexpr std::size_t report_frames = 6, report_footprints = 3;

// The name of the folder DIR, as a page's title shows it.
std::string folder_name(const std::string& dir);

// Writes DIR/report.html and the plots; returns the page's path. Throws std::invalid_argument when
// DIR holds no run (no summary.json and no scene.resolved.toml), std::runtime_error when a file
// cannot be read or written.
std::string write_run_report(const std::string& dir);

}  // namespace firn::report
