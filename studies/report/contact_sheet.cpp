#include "studies/report/contact_sheet.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>

#include "engine/output/png_file.hpp"
#include "studies/report/numbered_files.hpp"

namespace firn::report {
namespace {

const Rgb kInk = {0.12f, 0.12f, 0.14f};
constexpr std::uint8_t kPaper = 255;
constexpr int kGap = 6, kLineHeight = 10;  // stb_easy_font's letters are 7 pixels high at scale 1

// `image` shrunk by `factor` in each direction, each pixel the mean of a factor x factor block.
Image shrunk(const Image& image, int factor) {
  Image out(image.width / factor, image.height / factor);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x)
      for (int k = 0; k < 3; ++k) {
        int sum = 0;
        for (int dy = 0; dy < factor; ++dy)
          for (int dx = 0; dx < factor; ++dx)
            sum += image.rgb[(std::size_t(y * factor + dy) * std::size_t(image.width) + std::size_t(x * factor + dx)) * 3 +
                             std::size_t(k)];
        out.pixel(x, y)[k] = std::uint8_t(sum / (factor * factor));
      }
  return out;
}

}  // namespace

Image contact_sheet(const std::vector<ContactTile>& tiles, int columns, int max_tile_width) {
  int frame_w = 1, frame_h = 1;
  std::size_t lines = 1;
  for (const ContactTile& t : tiles) {
    frame_w = std::max(frame_w, t.frame.width), frame_h = std::max(frame_h, t.frame.height);
    lines = std::max(lines, t.label.size());
  }
  const int factor = std::max(1, (frame_w + max_tile_width - 1) / max_tile_width);
  const int tile_w = std::max(1, frame_w / factor), tile_h = std::max(1, frame_h / factor);
  // Labels twice the font's size where every line fits the tile.
  int scale = 2;
  for (const ContactTile& t : tiles)
    for (const std::string& line : t.label)
      if (text_width(line, 2) > tile_w) scale = 1;
  const int band = int(lines) * kLineHeight * scale + kGap;
  columns = std::max(1, std::min(columns, int(tiles.size())));
  const int rows = (int(tiles.size()) + columns - 1) / columns;
  Image sheet(kGap + columns * (tile_w + kGap), kGap + rows * (band + tile_h + kGap));
  std::fill(sheet.rgb.begin(), sheet.rgb.end(), kPaper);
  for (std::size_t i = 0; i < tiles.size(); ++i) {
    const int x0 = kGap + int(i) % columns * (tile_w + kGap), y0 = kGap + int(i) / columns * (band + tile_h + kGap);
    for (std::size_t l = 0; l < tiles[i].label.size(); ++l)
      draw_text(sheet, x0, y0 + int(l) * kLineHeight * scale, tiles[i].label[l], kInk, scale);
    const int top = y0 + band;
    if (tiles[i].frame.width == 0) {
      draw_text(sheet, x0, top + tile_h / 2, "no such frame", kInk, scale);
      continue;
    }
    blit(sheet, shrunk(tiles[i].frame, factor), x0, top);
  }
  return sheet;
}

int contact_sheet_columns(const sweep::SweepPlan& plan) {
  if (plan.keys.size() > 1) return int(plan.keys.back().values.size());
  return int(std::ceil(std::sqrt(double(plan.combinations.size()))));
}

std::vector<std::string> write_contact_sheets(const sweep::SweepPlan& plan) {
  std::set<int> numbers;
  for (std::size_t i = 0; i < plan.combinations.size(); ++i)
    for (const std::string& name : numbered_files(sweep::run_dir(plan, i), "frames", ".png"))
      numbers.insert(frame_number(name));
  if (numbers.empty()) return {};
  const int last = *numbers.rbegin(), middle = *std::next(numbers.begin(), std::ptrdiff_t(numbers.size() / 2));
  const int columns = contact_sheet_columns(plan);
  const int max_tile_width = std::min(640, 1800 / columns);
  std::vector<std::string> paths;
  for (const int number : std::set<int>{middle, last}) {
    char name[32];
    std::snprintf(name, sizeof name, "%05d.png", number);
    const std::string frame = std::string("/frames/") + name;
    std::vector<ContactTile> tiles;
    for (std::size_t i = 0; i < plan.combinations.size(); ++i) {
      ContactTile tile;
      for (std::size_t k = 0; k < plan.keys.size(); ++k)
        tile.label.push_back(plan.keys[k].key + " = " + plan.combinations[i][k]);
      const std::string path = sweep::run_dir(plan, i) + frame;
      if (std::filesystem::exists(path)) {
        tile.frame = read_png_rgb(path);
      }
      tiles.push_back(std::move(tile));
    }
    std::filesystem::create_directories(plan.out + "/contact_sheets");
    paths.push_back(plan.out + "/contact_sheets/" + name);
    write_png(paths.back(), contact_sheet(tiles, columns, max_tile_width));
  }
  return paths;
}

}  // namespace firn::report
