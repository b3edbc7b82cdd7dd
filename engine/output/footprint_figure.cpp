#include "engine/output/footprint_figure.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "engine/output/colour_map.hpp"

namespace firn {
namespace {

const Rgb kInk = {0.12f, 0.12f, 0.14f};
const Rgb kPaper = {1, 1, 1};
const Rgb kNoContact = {0.90f, 0.90f, 0.90f};
const Rgb kOutline = {1, 1, 1};
constexpr int kFont = 2;        // stb_easy_font pixels per font pixel
constexpr int kLine = 13 * kFont;
constexpr int kTick = 6;

std::string format(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

// Ticks at 1, 2 or 5 times a power of ten: the smallest such step giving at most `most` intervals
// over [lo, hi].
std::vector<double> nice_ticks(double lo, double hi, int most) {
  std::vector<double> ticks;
  if (!(hi > lo)) return {lo};
  const double raw = (hi - lo) / most, power = std::pow(10.0, std::floor(std::log10(raw)));
  double step = 10 * power;
  for (double m : {1.0, 2.0, 5.0})
    if (m * power >= raw) {
      step = m * power;
      break;
    }
  for (double t = std::ceil(lo / step - 1e-9) * step; t <= hi + 1e-9 * step; t += step)
    ticks.push_back(std::fabs(t) < 1e-9 * step ? 0.0 : t);
  return ticks;
}

Rgb viridis_rgb(double t) {
  const auto c = viridis(t);
  return {c[0], c[1], c[2]};
}

// The cover at every pixel of a w x h map, evaluated at the corners of 4 x 4 tiles and inside only
// the tiles whose corners differ (a footprint file of the preview tire took 150 ms with every pixel
// evaluated, 26 ms so): a groove or block narrower than a tile (2.5 mm at 640 pixels over a 40 cm
// window) can be missed.
template <class X, class Z>
std::vector<TreadCover> tread_cover_pixels(const TreadCoverAt& tread, int w, int h, X world_x, Z world_z) {
  constexpr int kTile = 4;
  const int tw = (w + kTile - 1) / kTile, th = (h + kTile - 1) / kTile;
  std::vector<TreadCover> corner(std::size_t(tw + 1) * std::size_t(th + 1));
  for (int ty = 0; ty <= th; ++ty)
    for (int tx = 0; tx <= tw; ++tx)
      corner[std::size_t(ty) * std::size_t(tw + 1) + std::size_t(tx)] =
          tread(world_x(std::min(tx * kTile, w - 1)), world_z(std::min(ty * kTile, h - 1)));
  std::vector<TreadCover> cover(std::size_t(w) * std::size_t(h));
  for (int ty = 0; ty < th; ++ty)
    for (int tx = 0; tx < tw; ++tx) {
      const TreadCover* c = &corner[std::size_t(ty) * std::size_t(tw + 1) + std::size_t(tx)];
      const bool uniform = c[0] == c[1] && c[0] == c[tw + 1] && c[0] == c[tw + 2];
      for (int py = ty * kTile; py < std::min(h, (ty + 1) * kTile); ++py)
        for (int px = tx * kTile; px < std::min(w, (tx + 1) * kTile); ++px)
          cover[std::size_t(py) * std::size_t(w) + std::size_t(px)] = uniform ? c[0] : tread(world_x(px), world_z(py));
    }
  return cover;
}

}  // namespace

FootprintStats footprint_stats(const FootprintField& f) {
  FootprintStats s;
  for (double p : f.pressure) s.peak = std::max(s.peak, p);
  if (!(s.peak > 0)) return s;
  int n = 0;
  double sum = 0;
  for (double p : f.pressure)
    if (p > FootprintStats::kPatchFraction * s.peak) ++n, sum += p;
  s.area = n * f.dx * f.dx;
  s.mean = sum / n;
  return s;
}

Image draw_footprint_figure(const FootprintField& f, const FootprintFigureSpec& spec) {
  const FootprintStats stats = footprint_stats(f);
  const double top = spec.pressure_max > 0 ? spec.pressure_max : stats.peak;
  // The map: columns drawn as cells of dx, the window's width spread over kPlotWidth pixels.
  constexpr int kPlotWidth = 640, kLeft = 90, kRight = 150, kTop = 3 * kLine + 10, kBottom = 3 * kLine + 12;
  const double x_lo = f.x0 - 0.5 * f.dx, z_hi = f.z0 + (f.nz - 0.5) * f.dx;
  const double scale = kPlotWidth / (f.nx * f.dx);  // pixels per metre
  const int plot_h = std::max(40, int(std::lround(f.nz * f.dx * scale)));
  const int bar_h = std::max(plot_h, 160);
  Image image(kLeft + kPlotWidth + kRight, kTop + bar_h + kBottom);
  fill_rect(image, 0, 0, image.width, image.height, kPaper);

  auto world_x = [&](int px) { return x_lo + (px + 0.5) / scale; };
  auto world_z = [&](int py) { return z_hi - (py + 0.5) / scale; };
  const std::vector<TreadCover> cover = spec.tread ? tread_cover_pixels(spec.tread, kPlotWidth, plot_h, world_x, world_z)
                                                   : std::vector<TreadCover>{};
  for (int py = 0; py < plot_h; ++py)
    for (int px = 0; px < kPlotWidth; ++px) {
      const int i = std::clamp(int((px + 0.5) / scale / f.dx), 0, f.nx - 1);
      const int k = std::clamp(f.nz - 1 - int((py + 0.5) / scale / f.dx), 0, f.nz - 1);
      const double p = f.at(i, k);
      Rgb c = p > 0 ? viridis_rgb(top > 0 ? p / top : 0) : kNoContact;
      if (!cover.empty()) {  // an edge between block, groove and outside
        const TreadCover here = cover[std::size_t(py) * kPlotWidth + std::size_t(px)];
        const bool edge = (px + 1 < kPlotWidth && cover[std::size_t(py) * kPlotWidth + std::size_t(px + 1)] != here) ||
                          (py + 1 < plot_h && cover[std::size_t(py + 1) * kPlotWidth + std::size_t(px)] != here);
        if (edge) c = kOutline;
      }
      fill_rect(image, kLeft + px, kTop + py, kLeft + px + 1, kTop + py + 1, c);
    }

  // Axes in mm about the axle, with a frame around the map.
  const int x1 = kLeft + kPlotWidth, y1 = kTop + plot_h;
  fill_rect(image, kLeft - 1, kTop - 1, x1 + 1, kTop, kInk);
  fill_rect(image, kLeft - 1, y1, x1 + 1, y1 + 1, kInk);
  fill_rect(image, kLeft - 1, kTop - 1, kLeft, y1 + 1, kInk);
  fill_rect(image, x1, kTop - 1, x1 + 1, y1 + 1, kInk);
  const double mm = 1e3;
  for (double t : nice_ticks((x_lo - spec.axle_x) * mm, (x_lo + kPlotWidth / scale - spec.axle_x) * mm, 8)) {
    const int px = kLeft + int(std::lround((t / mm + spec.axle_x - x_lo) * scale));
    fill_rect(image, px, y1, px + 1, y1 + kTick, kInk);
    const std::string label = format("%g", t);
    draw_text(image, px - text_width(label, kFont) / 2, y1 + kTick + 3, label, kInk, kFont);
  }
  const std::string x_label = "circumferential x (mm), axle at 0";
  draw_text(image, kLeft + (kPlotWidth - text_width(x_label, kFont)) / 2, y1 + kTick + 3 + kLine, x_label, kInk, kFont);
  for (double t : nice_ticks((z_hi - plot_h / scale - spec.axle_z) * mm, (z_hi - spec.axle_z) * mm, 6)) {
    const int py = kTop + int(std::lround((z_hi - (t / mm + spec.axle_z)) * scale));
    fill_rect(image, kLeft - kTick, py, kLeft, py + 1, kInk);
    const std::string label = format("%g", t);
    draw_text(image, kLeft - kTick - 4 - text_width(label, kFont), py - 5 * kFont, label, kInk, kFont);
  }
  draw_text(image, 8, kTop - kLine, "lateral z (mm)", kInk, kFont);

  // The colour bar in kPa.
  const int bx = x1 + 24, bw = 22;
  fill_rect(image, bx - 1, kTop - 1, bx + bw + 1, kTop + bar_h + 1, kInk);
  for (int y = 0; y < bar_h; ++y) fill_rect(image, bx, kTop + y, bx + bw, kTop + y + 1, viridis_rgb(1 - (y + 0.5) / bar_h));
  const double kpa = 1e-3;
  for (double t : top > 0 ? nice_ticks(0, top * kpa, 6) : std::vector<double>{}) {
    const int py = kTop + bar_h - int(std::lround(t / (top * kpa) * bar_h));
    fill_rect(image, bx + bw, py, bx + bw + kTick, py + 1, kInk);
    draw_text(image, bx + bw + kTick + 4, py - 5 * kFont, format("%g", t), kInk, kFont);
  }
  draw_text(image, bx - 4, kTop - kLine, "kPa", kInk, kFont);

  // Title, the patch's figures, and how to read the colours.
  draw_text(image, 8, 6, spec.title, kInk, kFont);
  const std::string figures =
      stats.peak > 0 ? spec.patch + format(" %.1f cm2", stats.area * 1e4) + format(", mean %.3g kPa", stats.mean * kpa) +
                           format(", peak %.3g kPa", stats.peak * kpa)
                     : "nothing above zero in this frame";
  draw_text(image, 8, 6 + kLine, figures, kInk, kFont);
  const std::string key = "grey: " + spec.empty + (spec.tread ? "; white: tread outline at the frame's end" : "");
  draw_text(image, 8, image.height - kLine, key, kInk, kFont);
  return image;
}

}  // namespace firn
