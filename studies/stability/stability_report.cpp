#include "studies/stability/stability_report.hpp"

#include "engine/output/atomic_file.hpp"
#include "studies/sweep/csv.hpp"

namespace firn::study {

using sweep::csv_field;
using sweep::csv_number;

void StabilityReport::add(const StabilityRow& row) {
  rows_.push_back(row);
  write_file_atomically(dir_ + "/stability.csv", csv());
}

std::string StabilityReport::csv() const {
  std::string out = "check,subject,setting,value,unit,outcome,detail,seconds\n";
  for (const StabilityRow& r : rows_)
    out += csv_field(r.check) + "," + csv_field(r.subject) + "," + csv_field(r.setting) + "," +
           (r.value ? csv_number(*r.value) : "") + "," + csv_field(r.unit) + "," + csv_field(r.outcome) + "," +
           csv_field(r.detail) + "," + csv_number(r.seconds) + "\n";
  return out;
}

namespace {

// A table cell: '|' escaped, line breaks as spaces.
std::string md_cell(std::string text) {
  std::string out;
  for (char c : text) {
    if (c == '|') out += "\\|";
    else if (c == '\n') out += ' ';
    else out += c;
  }
  return out;
}

}  // namespace

std::string StabilityReport::markdown(const std::string& notes) const {
  std::string out =
      "# firn study stability\n\n"
      "| check | subject | measure | value | outcome | detail |\n|---|---|---|---|---|---|\n";
  for (const StabilityRow& r : rows_) {
    if (!r.headline) continue;
    const std::string value = r.value ? csv_number(*r.value) + (r.unit.empty() ? "" : " " + r.unit) : "";
    out += "| " + md_cell(r.check) + " | " + md_cell(r.subject) + " | " + md_cell(r.setting) + " | " + md_cell(value) +
           " | " + md_cell(r.outcome) + " | " + md_cell(r.detail) + " |\n";
  }
  return out + "\n" + notes;
}

void StabilityReport::write_markdown(const std::string& notes) const {
  write_file_atomically(dir_ + "/stability.md", markdown(notes));
}

}  // namespace firn::study
