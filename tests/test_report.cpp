// firn report's parts (studies/report/): HTML escaping and tables, the numbered files a page picks,
// the thesis' Table 5.1 as a pivot of sweep.csv, and the scene parameters of scene.resolved.toml.
// The pages end to end, in a browser too, are in report_test.py.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "studies/report/html_writer.hpp"
#include "studies/report/numbered_files.hpp"
#include "studies/report/pivot_table.hpp"
#include "studies/report/scene_parameters.hpp"

namespace firn::report {
namespace {

using Strings = std::vector<std::string>;

TEST(HtmlWriter, EscapesTextInElementsAndAttributes) {
  EXPECT_EQ(html_escaped(R"(<a href="x">&'</a>)"), "&lt;a href=&quot;x&quot;&gt;&amp;&#39;&lt;/a&gt;");
  EXPECT_EQ(html_paragraph("1 < 2"), "<p>1 &lt; 2</p>\n");
  EXPECT_EQ(html_link("a\"b.png", "<b>"), "<a href=\"a&quot;b.png\">&lt;b&gt;</a>");
  const std::string figure = html_figure("frames/00001.png", "frame <1>");
  EXPECT_NE(figure.find("<img src=\"frames/00001.png\" alt=\"frame &lt;1&gt;\">"), std::string::npos) << figure;
}

TEST(HtmlWriter, TableEscapesCellsAndAlignsNumbers) {
  HtmlTable t;
  t.caption = "a & b";
  t.groups = {{"", 1}, {"g", 2}};
  t.header = {"key", "x", "y"};
  t.rows = {{"<script>", "1.5e-3", "n/a"}};
  const std::string html = html_table(t);
  EXPECT_NE(html.find("<caption>a &amp; b</caption>"), std::string::npos) << html;
  EXPECT_NE(html.find("<th colspan=\"2\">g</th>"), std::string::npos) << html;
  EXPECT_NE(html.find("<td>&lt;script&gt;</td><td class=\"num\">1.5e-3</td><td>n/a</td>"), std::string::npos) << html;
  t.first_cells_html = true;
  t.rows = {{"<a href=\"r.html\">1</a>", "<x>"}};
  EXPECT_NE(html_table(t).find("<td><a href=\"r.html\">1</a></td><td>&lt;x&gt;</td>"), std::string::npos);
}

TEST(HtmlWriter, PageIsSelfContained) {
  const std::string page = html_page("run <1>", "<p>body</p>\n");
  EXPECT_EQ(page.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(page.find("<title>run &lt;1&gt;</title>"), std::string::npos);
  EXPECT_NE(page.find("<h1>run &lt;1&gt;</h1>\n<p>body</p>"), std::string::npos);
  EXPECT_NE(page.find("data-report-check"), std::string::npos);
  for (const char* external : {"http://", "https://", "<link", "src=\"//"})
    EXPECT_EQ(page.find(external), std::string::npos) << external;
}

TEST(NumberedFiles, ListsFrameFilesInOrderAndPicksEvenly) {
  const std::string dir = ::testing::TempDir() + "firn_report_numbered";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir + "/frames");
  for (const char* name : {"00010.png", "00002.png", "00000.png", "100000.png", "notes.png", "00003.csv", "00004.png.tmp"})
    std::ofstream(dir + "/frames/" + name) << "x";
  EXPECT_EQ(numbered_files(dir, "frames", ".png"),
            (Strings{"frames/00000.png", "frames/00002.png", "frames/00010.png", "frames/100000.png"}));
  EXPECT_TRUE(numbered_files(dir, "footprint", ".png").empty());
  EXPECT_EQ(frame_number("frames/00010.png"), 10);

  const Strings items = {"0", "1", "2", "3", "4", "5", "6", "7", "8", "9"};
  EXPECT_EQ(evenly_spaced(items, 3), (Strings{"0", "4", "9"}));
  EXPECT_EQ(evenly_spaced(items, 6), (Strings{"0", "1", "3", "5", "7", "9"}));
  EXPECT_EQ(evenly_spaced(items, 1), (Strings{"9"}));
  EXPECT_EQ(evenly_spaced(items, 20), items);
  EXPECT_TRUE(evenly_spaced(items, 0).empty());
}

// sweep.csv of the thesis' matrix cut down: snow x tread, --at 0.01.
const char* const kSweepCsv =
    "materials.snow.preset,tire.tread,status,steps,particles,wall_seconds,particle_steps_per_second,"
    "mean_displaced,displaced@0.01,mean_traction,traction@0.01\n"
    "hard,bowtie,ok,10,100,1,1000,5,4,0.1,0.2\n"
    "hard,six_rib,ok,10,100,1,1000,6,8,0.1,0.2\n"
    "soft,bowtie,ok,10,100,1,1000,10,6,0.1,0.2\n"
    "soft,six_rib,unstable,10,100,1,1000,,,0.1,0.2\n";

TEST(PivotTable, TheThesisTable51BySnowAndTread) {
  const CsvTable csv = parse_csv(kSweepCsv);
  ASSERT_EQ(csv.rows.size(), 4u);
  EXPECT_EQ(varied_key_columns(csv), 2u);
  const HtmlTable t = pivot_table(csv, "displaced");
  EXPECT_EQ(t.caption, "displaced by tire.tread (rows) and materials.snow.preset (columns); ratio: soft / hard");
  EXPECT_EQ(t.groups, (std::vector<std::pair<std::string, int>>{{"", 1}, {"mean_displaced", 3}, {"displaced@0.01", 3}}));
  EXPECT_EQ(t.header, (Strings{"tire.tread", "hard", "soft", "ratio", "hard", "soft", "ratio"}));
  ASSERT_EQ(t.rows.size(), 2u);
  EXPECT_EQ(t.rows[0], (Strings{"bowtie", "5", "10", "2", "4", "6", "1.5"}));
  EXPECT_EQ(t.rows[1], (Strings{"six_rib", "6", "", "", "8", "", ""}));  // no value, no ratio
  EXPECT_TRUE(pivot_table(csv, "accumulated").rows.empty());           // not in sweep.csv
  EXPECT_TRUE(pivot_table(csv, "displace").rows.empty());              // a prefix is not the metric
}

TEST(PivotTable, OneKeyIsOneRowAndThreeValuesHaveNoRatio) {
  const CsvTable csv = parse_csv("tire.speed,status,mean_displaced\n5 mph,ok,1\n10 mph,ok,2\n20 mph,ok,3\n");
  const HtmlTable t = pivot_table(csv, "displaced");
  EXPECT_EQ(t.header, (Strings{"", "5 mph", "10 mph", "20 mph"}));
  ASSERT_EQ(t.rows.size(), 1u);
  EXPECT_EQ(t.rows[0], (Strings{"all runs", "1", "2", "3"}));
}

TEST(SceneParameters, ShowsTheSimulatedSectionsEscaped) {
  const std::string html = scene_parameters_html(R"(
[simulation]
dx = 0.004
end_time = 0.25
[materials.snow]
model = "snow<stomakhin>"
density = 400.0
[[bodies]]
name = "bed"
shape = "box"
[[bodies]]
name = "ball"
radius = 0.1
[tire]
tread = "bowtie"
center = [0.0, 0.265, 0.0]
[render]
width = 320
)");
  for (const char* expected :
       {"<caption>[simulation]</caption>", "<td>dx</td><td class=\"num\">0.004</td>", "<caption>[materials.snow]</caption>",
        "<td>snow&lt;stomakhin&gt;</td>", "<caption>[[bodies]]</caption>", "<th>name</th><th>shape</th><th>radius</th>",
        "<td>ball</td><td></td><td class=\"num\">0.1</td>", "<caption>[tire]</caption>", "<td>bowtie</td>"})
    EXPECT_NE(html.find(expected), std::string::npos) << expected << "\n" << html;
  EXPECT_EQ(html.find("render"), std::string::npos);  // the rendering settings are in the linked file
  EXPECT_THROW(scene_parameters_html("[simulation\n"), std::runtime_error);
}

}  // namespace
}  // namespace firn::report
