// The footprints of a sweep's runs side by side (issue 18 item 4; the thesis' Figure 5.7 lays out
// the three treads' stress maps together): each run's last footprint (footprint/NNNNN.csv, or a
// rubber tire's tread_stress/NNNNN.csv) drawn
// as a footprint figure on one colour scale, labelled with the run's varied values, three to a row.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "engine/output/footprint_figure.hpp"

namespace firn::sweep {

struct FootprintPanel {
  std::string label;  // e.g. "tire.tread=six_rib"
  FootprintField field;
  bool tread_stress = false;  // a rubber tire's tread stress, not a footprint's pressure
};

// The last footprint CSV (the highest frame number) under RUN_DIR/footprint, or a rubber tire's
// tread stress under RUN_DIR/tread_stress (engine/output/tread_stress.hpp), unlabelled; none when
// there is neither or it cannot be read.
std::optional<FootprintPanel> last_footprint(const std::string& run_dir);

// The panels drawn on the largest peak among them, in rows of up to `per_row`.
Image footprint_comparison(const std::vector<FootprintPanel>& panels, int per_row = 3);

}  // namespace firn::sweep
