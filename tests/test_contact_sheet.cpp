// A sweep's contact sheets (studies/report/contact_sheet.hpp): where each run's tile lands in the
// grid, that frames are shrunk by a whole factor, that the labels are drawn above the frames, and
// that a missing frame leaves a labelled tile; the frames read back through read_png_rgb.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "engine/output/png_file.hpp"
#include "studies/report/contact_sheet.hpp"

namespace firn::report {
namespace {

Image solid(int w, int h, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  Image image(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) image.pixel(x, y)[0] = r, image.pixel(x, y)[1] = g, image.pixel(x, y)[2] = b;
  return image;
}

bool is(Image& image, int x, int y, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  const std::uint8_t* p = image.pixel(x, y);
  return p[0] == r && p[1] == g && p[2] == b;
}

// Pixels darker than mid-grey in the rectangle [x0, x1) x [y0, y1): drawn text.
int dark_pixels(Image& image, int x0, int y0, int x1, int y1) {
  int n = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) n += image.pixel(x, y)[0] < 128;
  return n;
}

TEST(ContactSheet, PlacesTilesRowByRowUnderTheirLabels) {
  // Four 400 x 200 frames, at most 200 pixels a tile: shrunk by 2 to 200 x 100, two columns.
  std::vector<ContactTile> tiles = {{{"a = 1", "b = x"}, solid(400, 200, 255, 0, 0)},
                                    {{"a = 1", "b = y"}, solid(400, 200, 0, 255, 0)},
                                    {{"a = 2", "b = x"}, solid(400, 200, 0, 0, 255)},
                                    {{"a = 2", "b = y"}, Image()}};
  Image sheet = contact_sheet(tiles, 2, 200);
  // Labels at twice the font's size ("a = 1" is 5 letters, well under 200 pixels): two lines of
  // 20 pixels and a 6-pixel gap above each frame; tiles 6 pixels apart and from the edges.
  const int gap = 6, band = 2 * 20 + gap, tile_w = 200, tile_h = 100;
  ASSERT_EQ(sheet.width, gap + 2 * (tile_w + gap));
  ASSERT_EQ(sheet.height, gap + 2 * (band + tile_h + gap));
  const int x[2] = {gap, gap + tile_w + gap}, y[2] = {gap + band, gap + band + tile_h + gap + band};
  EXPECT_TRUE(is(sheet, x[0], y[0], 255, 0, 0));
  EXPECT_TRUE(is(sheet, x[0] + tile_w - 1, y[0] + tile_h - 1, 255, 0, 0));
  EXPECT_TRUE(is(sheet, x[1], y[0], 0, 255, 0));
  EXPECT_TRUE(is(sheet, x[0], y[1], 0, 0, 255));
  EXPECT_TRUE(is(sheet, x[0] + tile_w, y[0], 255, 255, 255));  // the gap between tiles
  EXPECT_TRUE(is(sheet, x[0], y[0] - 1, 255, 255, 255));        // the band above a frame ...
  for (int row = 0; row < 2; ++row)
    for (int col = 0; col < 2; ++col)  // ... holds its two label lines
      for (int line = 0; line < 2; ++line) {
        const int top = y[row] - band + line * 20;
        EXPECT_GT(dark_pixels(sheet, x[col], top, x[col] + tile_w, top + 20), 20) << row << col << line;
      }
  // The run without the frame: white, and a note in its middle.
  EXPECT_TRUE(is(sheet, x[1] + tile_w - 1, y[1] + tile_h - 1, 255, 255, 255));
  EXPECT_GT(dark_pixels(sheet, x[1], y[1], x[1] + tile_w, y[1] + tile_h), 20);
}

TEST(ContactSheet, ShrinksLabelsThatDoNotFitAndAveragesPixels) {
  const std::string label = "materials.snow.preset = thesis_soft_snow";
  ASSERT_GT(text_width(label, 2), 150);
  Image frame = solid(300, 150, 0, 0, 0);
  for (int y = 0; y < 150; ++y)
    for (int x = 0; x < 300; x += 2) frame.pixel(x, y)[0] = 200;  // stripes one pixel wide ...
  Image sheet = contact_sheet({{{label}, frame}}, 4, 150);
  EXPECT_EQ(sheet.width, 6 + 150 + 6);          // one tile: the columns never exceed the tiles
  EXPECT_EQ(sheet.height, 6 + (10 + 6) + 75 + 6);  // one line at the font's own size
  EXPECT_TRUE(is(sheet, 6 + 10, 6 + 16 + 10, 100, 0, 0));  // ... averaged by the 2 x 2 shrink
}

TEST(ContactSheet, FramesReadBackFromPng) {
  Image image(37, 23);
  for (std::size_t i = 0; i < image.rgb.size(); ++i) image.rgb[i] = std::uint8_t((i * 7919) % 251);
  const std::string path = ::testing::TempDir() + "firn_contact_sheet_frame.png";
  write_png(path, image);
  const Image back = read_png_rgb(path);
  EXPECT_EQ(back.width, 37);
  EXPECT_EQ(back.height, 23);
  EXPECT_EQ(back.rgb, image.rgb);
  EXPECT_THROW(read_png_rgb(path + ".absent"), std::runtime_error);
}

}  // namespace
}  // namespace firn::report
