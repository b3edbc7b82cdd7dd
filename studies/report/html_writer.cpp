#include "studies/report/html_writer.hpp"

#include <cstdlib>

namespace firn::report {
namespace {

bool is_number(const std::string& text) {
  if (text.empty()) return false;
  char* end = nullptr;
  std::strtod(text.c_str(), &end);
  return *end == '\0';
}

std::string cell(const char* tag, const std::string& html, bool number) {
  return std::string("<") + tag + (number ? " class=\"num\">" : ">") + html + "</" + tag + ">";
}

// Kept small and plain: the page is read on screen and printed.
const char* const kStyle = R"(
body { font-family: sans-serif; margin: 1.5em auto; max-width: 1200px; padding: 0 1em; color: #1e1e24; background: #fff; }
h1 { font-size: 1.6em; } h2 { font-size: 1.3em; margin-top: 1.6em; border-bottom: 1px solid #ccd; }
table { border-collapse: collapse; margin: 0.5em 0 1em; font-size: 0.9em; }
caption { text-align: left; font-weight: bold; padding: 0.3em 0; }
th, td { border: 1px solid #ccd; padding: 0.2em 0.5em; text-align: left; vertical-align: top; }
th { background: #eef0f6; } td.num { text-align: right; font-variant-numeric: tabular-nums; }
.gallery { display: flex; flex-wrap: wrap; gap: 0.6em; }
figure { margin: 0; } figure img { max-width: 100%; border: 1px solid #ccd; }
figcaption { font-size: 0.85em; color: #555; }
video { max-width: 100%; }
.check { background: #fde2e1; border: 1px solid #c33; padding: 0.5em; }
)";

// Collects failed loads (images, the video) and script errors as they happen; images that never
// finished are counted once the page has loaded.
const char* const kCheck = R"(
(function () {
  var problems = [];
  window.addEventListener('error', function (e) {
    var t = e.target;
    if (t && t.tagName === 'IMG') return;  // counted with the other images below
    problems.push(t && t.tagName ? t.tagName.toLowerCase() + ' ' + t.getAttribute('src') + ' did not load'
                                 : 'script error: ' + e.message);
  }, true);
  window.addEventListener('load', function () {
    Array.prototype.forEach.call(document.images, function (img) {
      if (!(img.complete && img.naturalWidth > 0)) problems.push('image ' + img.getAttribute('src') + ' did not load');
    });
    document.documentElement.setAttribute('data-report-check', problems.length ? problems.join('; ') : 'ok');
    if (problems.length) {
      var note = document.createElement('p');
      note.className = 'check';
      note.textContent = 'This page is missing parts (was it moved without the files beside it?): ' + problems.join('; ');
      document.body.insertBefore(note, document.body.firstChild);
    }
  });
})();
)";

}  // namespace

std::string html_escaped(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string html_heading(int level, const std::string& text) {
  const std::string tag = "h" + std::to_string(level);
  return "<" + tag + ">" + html_escaped(text) + "</" + tag + ">\n";
}

std::string html_paragraph(const std::string& text) { return "<p>" + html_escaped(text) + "</p>\n"; }

std::string html_link(const std::string& href, const std::string& text) {
  return "<a href=\"" + html_escaped(href) + "\">" + html_escaped(text) + "</a>";
}

std::string html_table(const HtmlTable& table) {
  std::string s = "<table>\n";
  if (!table.caption.empty()) s += "<caption>" + html_escaped(table.caption) + "</caption>\n";
  if (!table.groups.empty()) {
    s += "<tr>";
    for (const auto& [text, span] : table.groups)
      s += "<th colspan=\"" + std::to_string(span) + "\">" + html_escaped(text) + "</th>";
    s += "</tr>\n";
  }
  s += "<tr>";
  for (const std::string& h : table.header) s += cell("th", html_escaped(h), false);
  s += "</tr>\n";
  for (const auto& row : table.rows) {
    s += "<tr>";
    for (std::size_t i = 0; i < row.size(); ++i)
      s += i == 0 && table.first_cells_html ? cell("td", row[i], false) : cell("td", html_escaped(row[i]), is_number(row[i]));
    s += "</tr>\n";
  }
  return s + "</table>\n";
}

std::string html_figure(const std::string& src, const std::string& caption, const std::string& href) {
  return "<figure><a href=\"" + html_escaped(href.empty() ? src : href) + "\"><img src=\"" + html_escaped(src) +
         "\" alt=\"" + html_escaped(caption) + "\"></a><figcaption>" + html_escaped(caption) +
         "</figcaption></figure>";
}

std::string html_gallery(const std::vector<std::string>& figures, int tile_px) {
  std::string s = "<div class=\"gallery\">\n";
  for (const std::string& f : figures)
    s += "<div style=\"width: " + std::to_string(tile_px) + "px\">" + f + "</div>\n";
  return s + "</div>\n";
}

std::string html_video(const std::string& src) {
  return "<video controls preload=\"metadata\" src=\"" + html_escaped(src) + "\"></video>\n";
}

std::string html_page(const std::string& title, const std::string& body) {
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" + html_escaped(title) +
         "</title>\n<style>" + kStyle + "</style>\n<script>" + kCheck + "</script>\n</head>\n<body>\n" +
         html_heading(1, title) + body + "</body>\n</html>\n";
}

}  // namespace firn::report
