#include "studies/sweep/footprint_comparison.hpp"

#include <algorithm>
#include <filesystem>

#include "engine/output/footprint_writer.hpp"
#include "engine/output/tread_stress.hpp"

namespace firn::sweep {

std::optional<FootprintPanel> last_footprint(const std::string& run_dir) {
  namespace fs = std::filesystem;
  for (const char* folder : {"footprint", "tread_stress"}) {  // a run writes one of them
    std::error_code error;
    std::string last;
    for (const auto& entry : fs::directory_iterator(run_dir + "/" + folder, error))
      if (entry.path().extension() == ".csv") last = std::max(last, entry.path().string());  // NNNNN: by frame
    if (last.empty()) continue;
    std::optional<FootprintField> field = read_footprint_csv(last);
    if (!field) return std::nullopt;
    return FootprintPanel{"", std::move(*field), std::string(folder) == "tread_stress"};
  }
  return std::nullopt;
}

Image footprint_comparison(const std::vector<FootprintPanel>& panels, int per_row) {
  if (panels.empty()) return Image();
  double peak = 0;
  for (const FootprintPanel& p : panels) peak = std::max(peak, footprint_stats(p.field).peak);
  std::vector<Image> figures;
  int w = 0, h = 0;
  for (const FootprintPanel& p : panels) {
    FootprintFigureSpec spec;
    // The window is centred on the axle (engine/scene/scene_metrics.hpp).
    spec.axle_x = p.field.x0 + 0.5 * (p.field.nx - 1) * p.field.dx;
    spec.axle_z = p.field.z0 + 0.5 * (p.field.nz - 1) * p.field.dx;
    spec.pressure_max = peak;
    spec.title = p.label;
    if (p.tread_stress) spec.patch = kTreadStressPatch, spec.empty = kTreadStressEmpty;
    figures.push_back(draw_footprint_figure(p.field, spec));
    w = std::max(w, figures.back().width), h = std::max(h, figures.back().height);
  }
  const int columns = std::min(per_row, int(figures.size()));
  const int rows = (int(figures.size()) + columns - 1) / columns;
  Image sheet(columns * w, rows * h);
  fill_rect(sheet, 0, 0, sheet.width, sheet.height, {1, 1, 1});
  for (std::size_t i = 0; i < figures.size(); ++i)
    blit(sheet, figures[i], int(i % std::size_t(columns)) * w, int(i / std::size_t(columns)) * h);
  return sheet;
}

}  // namespace firn::sweep
