// The pieces of firn's report pages (firn report, issue 18 item 5): one self-contained HTML file
// with its style inline and its images beside it, linked by relative paths, so that the page opens
// from a copied folder with no network. Every text argument is escaped here; `html` arguments are
// markup built by these functions.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace firn::report {

// `text` with &, <, >, " and ' replaced by character references: safe in an element and in a
// quoted attribute.
std::string html_escaped(const std::string& text);

// A heading, a paragraph, a link.
std::string html_heading(int level, const std::string& text);
std::string html_paragraph(const std::string& text);
std::string html_link(const std::string& href, const std::string& text);

// A table: optionally a row of column groups (text, columns spanned), a header row, then the
// rows; a cell that is a number is right-aligned. Cells are text, except that with
// `first_cells_html` the first cell of each row is markup (a link).
struct HtmlTable {
  std::string caption;
  std::vector<std::pair<std::string, int>> groups;
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  bool first_cells_html = false;
};
std::string html_table(const HtmlTable& table);

// An image with a caption under it, the image a link to `href` (empty: the image itself).
std::string html_figure(const std::string& src, const std::string& caption, const std::string& href = "");

// Figures side by side, wrapping; `tile_px`: the width each takes (an image narrower keeps its size).
std::string html_gallery(const std::vector<std::string>& figures, int tile_px);

// A video player for `src` (an MP4 beside the page).
std::string html_video(const std::string& src);

// The whole page: `title` and `body` in the page's style. The page says at its top when one of its
// images did not load or a script error occurred (a report moved without its images) and records
// the outcome in the root element's data-report-check attribute ("ok", or what failed), which the
// headless-browser test reads.
std::string html_page(const std::string& title, const std::string& body);

}  // namespace firn::report
