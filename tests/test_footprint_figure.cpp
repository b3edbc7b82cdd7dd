// The footprint figure (engine/output/footprint_figure.hpp), the tread cover drawn over it and the
// footprint files (engine/output/footprint_writer.hpp), and a sweep's comparison figure
// (studies/sweep/footprint_comparison.hpp): the patch's statistics, the map's colours and outline
// at known pixels, the figure's size, the CSV read back, the comparison's layout and common scale.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "engine/output/colour_map.hpp"
#include "engine/output/footprint_writer.hpp"
#include "engine/tread_patterns.hpp"
#include "studies/sweep/footprint_comparison.hpp"

namespace firn {
namespace {

// 20 x 10 columns of 1 cm from (-0.1, -0.05): 100 kPa on the 2 x 3 columns i 10..11, k 4..6, 2 kPa
// (2% of the peak: outside the patch) on column (0, 0), nothing elsewhere.
FootprintField test_field() {
  FootprintField f;
  f.x0 = -0.1, f.z0 = -0.05, f.dx = 0.01, f.nx = 20, f.nz = 10;
  f.pressure.assign(200, 0.0);
  for (int k = 4; k <= 6; ++k)
    for (int i = 10; i <= 11; ++i) f.pressure[std::size_t(k * 20 + i)] = 1e5;
  f.pressure[0] = 2e3;
  return f;
}

TEST(FootprintFigure, PatchStatisticsLeaveOutColumnsBelowFivePercentOfThePeak) {
  const FootprintStats s = footprint_stats(test_field());
  EXPECT_DOUBLE_EQ(s.peak, 1e5);
  EXPECT_NEAR(s.area, 6e-4, 1e-12);
  EXPECT_DOUBLE_EQ(s.mean, 1e5);
}

TEST(FootprintFigure, NoContactGivesZeroStatisticsAndStillDraws) {
  FootprintField f = test_field();
  std::fill(f.pressure.begin(), f.pressure.end(), 0.0);
  const FootprintStats s = footprint_stats(f);
  EXPECT_EQ(s.peak, 0);
  EXPECT_EQ(s.area, 0);
  const Image image = draw_footprint_figure(f, {});
  EXPECT_GE(image.width, kFootprintFigureMinWidth);
}

// The number of pixels of exactly colour c.
int count_colour(Image& image, const Rgb& c) {
  int count = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = image.pixel(x, y);
      bool same = true;
      for (int k = 0; k < 3; ++k) same = same && p[k] == std::uint8_t(std::lround(255 * c[std::size_t(k)]));
      count += same;
    }
  return count;
}

TEST(FootprintFigure, CellsKeepTheirAspectAndPeakIsTheTopOfTheColourMap) {
  Image image = draw_footprint_figure(test_field(), {});
  EXPECT_GE(image.width, kFootprintFigureMinWidth);
  // The patch: 2 x 3 columns of 1 cm at 640 px per 20 cm (32 px per cm) in viridis(1), plus the
  // colour bar's top rows in the same colour.
  const int patch = count_colour(image, viridis(1.0));
  EXPECT_GE(patch, 64 * 96);
  EXPECT_LE(patch, 64 * 96 + 22 * 3);
}

TEST(FootprintFigure, OutlineIsDrawnWhereTheCoverChanges) {
  FootprintFigureSpec spec;
  spec.tread = [](double x, double) { return x < 0 ? TreadCover::block : TreadCover::groove; };
  Image outlined = draw_footprint_figure(test_field(), spec);
  Image plain = draw_footprint_figure(test_field(), {});
  ASSERT_EQ(outlined.width, plain.width);
  ASSERT_EQ(outlined.height, plain.height);
  // White where the plain figure is not: one pixel per row of the map, all on one column (x = 0,
  // 10 cm from the window's left edge at 32 px per cm), and none elsewhere.
  auto white = [](const std::uint8_t* p) { return p[0] == 255 && p[1] == 255 && p[2] == 255; };
  int count = 0, min_x = 1 << 30, max_x = -1;
  for (int y = 0; y < plain.height; ++y)
    for (int x = 0; x < plain.width; ++x)
      if (white(outlined.pixel(x, y)) && !white(plain.pixel(x, y))) ++count, min_x = std::min(min_x, x), max_x = std::max(max_x, x);
  EXPECT_EQ(count, 320);  // 10 cm of map height
  EXPECT_EQ(min_x, max_x);
}

Collider<double> tire_collider(const char* tread) {
  Collider<double> c;
  c.shape = ColliderShape::tire;
  c.center[1] = 0.3;
  c.tire = make_tire_shape(tread, 0.2, 0.125, 0.012, 12);
  return c;
}

TEST(FootprintFigure, SlickTireCoversItsWidthWithinItsRadius) {
  Collider<double> c = tire_collider("angled_footstep");
  c.tire.block_count = 0;  // a slick tire: the band is solid rubber
  const TreadCoverAt cover = tread_cover(c);
  EXPECT_EQ(cover(0.0, 0.0), TreadCover::block);
  EXPECT_EQ(cover(0.19, 0.06), TreadCover::block);
  EXPECT_EQ(cover(0.0, 0.07), TreadCover::none);   // beyond the half width 62.5 mm
  EXPECT_EQ(cover(0.21, 0.0), TreadCover::none);   // beyond the radius
}

TEST(FootprintFigure, EachTreadShowsBlocksAndGroovesUnderTheAxle) {
  for (const char* tread : {"angled_footstep", "bowtie", "six_rib"}) {
    const TreadCoverAt cover = tread_cover(tire_collider(tread));
    int blocks = 0, grooves = 0;
    for (int i = -40; i <= 40; ++i)
      for (int k = -30; k <= 30; ++k) {
        const TreadCover c = cover(i * 1e-3, k * 2e-3);
        blocks += c == TreadCover::block, grooves += c == TreadCover::groove;
      }
    EXPECT_GT(blocks, 0) << tread;
    EXPECT_GT(grooves, 0) << tread;
  }
}

TEST(FootprintFiles, CsvIsReadBackAsWrittenAndTheLastFrameIsFound) {
  // A 30 x 20 map of 1 cm columns; the window keeps 11 x 5 of them around (0.15, 0.10).
  FootprintMap map;
  map.nx = 30, map.nz = 20, map.dx = 0.01, map.time = 0.5;
  map.impulse.resize(600);
  for (int i = 0; i < 30; ++i)
    for (int k = 0; k < 20; ++k) map.impulse[std::size_t(i * 20 + k)] = 1e-4 * (1 + i + 100 * k);
  const FootprintWindow window{0.15, 0.10, 0.05, 0.02};
  const FootprintField written = footprint_field(map, window);
  ASSERT_EQ(written.nx, 11);
  ASSERT_EQ(written.nz, 5);
  EXPECT_NEAR(written.at(0, 0), 1e-4 * (1 + 10 + 100 * 8) / (0.5 * 1e-4), 1e-9);

  const std::string dir = testing::TempDir() + "firn_footprint_files";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir + "/footprint");
  Collider<double> tire = tire_collider("six_rib");
  tire.center[0] = 0.15, tire.center[2] = 0.10;
  for (const char* frame : {"00002", "00010"})
    write_footprint(dir + "/footprint/" + frame, map, window, tire, "test");
  map.impulse[std::size_t(12 * 20 + 9)] = 1;  // only in frame 9, which is not the last
  write_footprint(dir + "/footprint/00009", map, window, tire, "test");
  EXPECT_TRUE(std::filesystem::is_regular_file(dir + "/footprint/00010.png"));

  const auto panel = sweep::last_footprint(dir);
  ASSERT_TRUE(panel.has_value());
  EXPECT_FALSE(panel->tread_stress);
  const FootprintField* read = &panel->field;
  EXPECT_EQ(read->nx, written.nx);
  EXPECT_EQ(read->nz, written.nz);
  EXPECT_NEAR(read->x0, written.x0, 1e-9);
  EXPECT_NEAR(read->z0, written.z0, 1e-9);
  EXPECT_NEAR(read->dx, written.dx, 1e-9);
  for (int k = 0; k < written.nz; ++k)
    for (int i = 0; i < written.nx; ++i) EXPECT_NEAR(read->at(i, k), written.at(i, k), 1e-5 * written.at(i, k));

  EXPECT_FALSE(sweep::last_footprint(dir + "/none").has_value());
  EXPECT_FALSE(read_footprint_csv(dir + "/footprint/00010.png").has_value());

  // A rubber tire's run has tread_stress/ instead: found, and marked so.
  const std::string rubber = dir + "/rubber";
  std::filesystem::create_directories(rubber + "/tread_stress");
  std::filesystem::copy_file(dir + "/footprint/00010.csv", rubber + "/tread_stress/00003.csv");
  const auto stress = sweep::last_footprint(rubber);
  ASSERT_TRUE(stress.has_value());
  EXPECT_TRUE(stress->tread_stress);
  EXPECT_EQ(stress->field.nx, written.nx);
}

TEST(FootprintComparison, PanelsShareOneColourScaleThreeToARow) {
  FootprintField half = test_field();
  for (double& p : half.pressure) p *= 0.5;
  const Image one = draw_footprint_figure(test_field(), {});
  Image sheet = sweep::footprint_comparison({{"a", test_field()}, {"b", half}, {"c", half}, {"d", half}});
  EXPECT_EQ(sheet.width, 3 * one.width);
  EXPECT_EQ(sheet.height, 2 * one.height);
  // On the common scale, only the first panel's patch reaches the top colour: its 64 x 96 pixels,
  // plus each colour bar's top rows.
  const int top = count_colour(sheet, viridis(1.0));
  EXPECT_GE(top, 64 * 96);
  EXPECT_LE(top, 64 * 96 + 4 * 22 * 3);
  EXPECT_EQ(sweep::footprint_comparison({}).width, 0);
}

}  // namespace
}  // namespace firn
