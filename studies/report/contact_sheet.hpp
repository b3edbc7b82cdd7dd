// Contact sheets for tuning (issue 18 item 6): the same frame of every run of a sweep rendered with
// --render, in one image, each run's tile labelled with its varied values, so that a person tuning
// parameters compares the runs at a glance. Written as contact_sheets/NNNNN.png in the sweep's
// folder, like a run's frames/NNNNN.png.
#pragma once

#include <string>
#include <vector>

#include "studies/sweep/sweep_plan.hpp"
#include "engine/output/image.hpp"

namespace firn::report {

struct ContactTile {
  std::vector<std::string> label;  // lines drawn above the frame, e.g. "tire.tread = bowtie"
  Image frame;                     // 0 x 0: the run has no such frame (the tile says so)
};

// The tiles in a grid of `columns`, row by row, every frame shrunk by the same whole factor so that
// no tile is wider than `max_tile_width` pixels, each under a band holding its label.
Image contact_sheet(const std::vector<ContactTile>& tiles, int columns, int max_tile_width);

// The grid's columns for a sweep: one per value of the last varied key when there are several
// keys (so that each row holds one combination of the others), else about the square root of the
// runs.
int contact_sheet_columns(const sweep::SweepPlan& plan);

// Writes PLAN.out/contact_sheets/NNNNN.png for the middle and the last frame number that any run's
// frames/ holds; returns their paths (none when no run has frames). Throws std::runtime_error when
// a frame cannot be read or a sheet written.
std::vector<std::string> write_contact_sheets(const sweep::SweepPlan& plan);

}  // namespace firn::report
