#include "studies/stability/stability_output_scan.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <sstream>

#include "studies/sweep/csv.hpp"
#include "studies/sweep/run_record.hpp"

namespace firn::study {
namespace {

// The value of attribute `name` inside one XML tag, or "".
std::string attribute(const std::string& tag, const std::string& name) {
  const std::string key = " " + name + "=\"";
  const std::size_t at = tag.find(key);
  if (at == std::string::npos) return "";
  const std::size_t begin = at + key.size(), end = tag.find('"', begin);
  return end == std::string::npos ? "" : tag.substr(begin, end - begin);
}

template <class T>
bool all_finite(const char* data, std::size_t bytes) {
  for (std::size_t i = 0; i + sizeof(T) <= bytes; i += sizeof(T)) {
    T v;
    std::memcpy(&v, data + i, sizeof(T));
    if (!std::isfinite(v)) return false;
  }
  return true;
}

}  // namespace

std::string non_finite_in_csv(const std::string& text) {
  std::istringstream in(text);
  std::string line;
  std::vector<std::string> header;
  for (long row = 0; std::getline(in, line); ++row) {
    const std::vector<std::string> cells = sweep::split_csv_line(line);
    if (row == 0) {
      header = cells;
      continue;
    }
    for (std::size_t c = 0; c < cells.size(); ++c) {
      std::string v = cells[c];
      for (char& ch : v) ch = char(std::tolower(static_cast<unsigned char>(ch)));
      if (v.find("nan") != std::string::npos || v.find("inf") != std::string::npos)
        return "column " + (c < header.size() ? header[c] : std::to_string(c + 1)) + ", row " + std::to_string(row);
    }
  }
  return "";
}

std::string non_finite_in_vtp(const std::string& bytes) {
  const std::string marker = "<AppendedData encoding=\"raw\">";
  const std::size_t appended = bytes.find(marker);
  if (appended == std::string::npos) return "malformed: no appended data";
  const std::size_t base = bytes.find('_', appended + marker.size());
  if (base == std::string::npos) return "malformed: no '_' before the appended data";
  std::size_t at = 0;
  while ((at = bytes.find("<DataArray ", at)) < appended) {
    const std::size_t end = bytes.find('>', at);
    const std::string tag = bytes.substr(at, end - at);
    at = end;
    const std::string type = attribute(tag, "type"), name = attribute(tag, "Name");
    if (type != "Float32" && type != "Float64") continue;
    const std::size_t offset = std::stoull(attribute(tag, "offset"));
    const std::size_t start = base + 1 + offset;
    std::uint64_t size = 0;
    if (start + sizeof size > bytes.size()) return "malformed: array " + name + " past the end of the file";
    std::memcpy(&size, bytes.data() + start, sizeof size);
    if (start + sizeof size + size > bytes.size()) return "malformed: array " + name + " past the end of the file";
    const char* data = bytes.data() + start + sizeof size;
    const bool finite = type == "Float32" ? all_finite<float>(data, size) : all_finite<double>(data, size);
    if (!finite) return "array " + (name.empty() ? std::string("Points") : name);
  }
  return "";
}

std::vector<std::string> non_finite_outputs(const std::string& run_dir) {
  namespace fs = std::filesystem;
  std::vector<std::string> found;
  const fs::path metrics = fs::path(run_dir) / "metrics.csv";
  if (fs::exists(metrics))
    if (const std::string where = non_finite_in_csv(sweep::file_text(metrics.string()).value_or("")); !where.empty())
      found.push_back(metrics.string() + ": " + where);
  const fs::path particles = fs::path(run_dir) / "particles";
  if (fs::is_directory(particles))
    for (const auto& entry : fs::directory_iterator(particles))
      if (entry.path().extension() == ".vtp")
        if (const std::string where = non_finite_in_vtp(sweep::file_text(entry.path().string()).value_or("")); !where.empty())
          found.push_back(entry.path().string() + ": " + where);
  return found;
}

}  // namespace firn::study
