#include "engine/output/vtp_writer.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "engine/output/atomic_file.hpp"
#include "engine/output/frame_files.hpp"

namespace firn {

void write_vtp(const std::string& path, std::size_t points, const std::vector<VtpLayout>& point_data,
               const VtpLayout& positions, const std::function<void(std::size_t, unsigned char*)>& fill,
               std::vector<unsigned char>& buffer) {
  // Verts: vertex i is point i (connectivity i, offsets i + 1), so viewers draw every point.
  const VtpLayout connectivity = vtp_layout<std::int32_t>("connectivity", 1), offsets = vtp_layout<std::int32_t>("offsets", 1);
  auto bytes_of = [points](const VtpLayout& a) { return points * std::size_t(a.components) * a.value_bytes; };

  std::uint64_t offset = 0;
  std::string xml;
  auto declare = [&](const VtpLayout& a, bool named) {
    xml += "<DataArray type=\"" + a.type + "\"" + (named ? " Name=\"" + a.name + "\"" : std::string()) +
           " NumberOfComponents=\"" + std::to_string(a.components) + "\" format=\"appended\" offset=\"" +
           std::to_string(offset) + "\"/>\n";
    offset += sizeof(std::uint64_t) + bytes_of(a);
  };
  xml += "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" "
         "header_type=\"UInt64\">\n<PolyData>\n<Piece NumberOfPoints=\"" + std::to_string(points) +
         "\" NumberOfVerts=\"" + std::to_string(points) +
         "\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n<PointData>\n";
  for (const VtpLayout& a : point_data) declare(a, true);
  xml += "</PointData>\n<Points>\n";
  declare(positions, false);
  xml += "</Points>\n<Verts>\n";
  declare(connectivity, true);
  declare(offsets, true);
  xml += "</Verts>\n</Piece>\n</PolyData>\n<AppendedData encoding=\"raw\">\n_";

  AtomicFile f(path);
  std::ofstream& out = f.stream();
  out << xml;
  auto append = [&](const VtpLayout& a, auto&& write_values) {
    const std::uint64_t size = bytes_of(a);
    if (buffer.size() < size) buffer.resize(size);
    write_values(buffer.data());
    out.write(reinterpret_cast<const char*>(&size), sizeof size);
    out.write(reinterpret_cast<const char*>(buffer.data()), std::streamsize(size));
  };
  for (std::size_t k = 0; k <= point_data.size(); ++k)
    append(k < point_data.size() ? point_data[k] : positions, [&](unsigned char* bytes) { fill(k, bytes); });
  for (std::int32_t first : {0, 1})  // connectivity i, then offsets i + 1
    append(first ? offsets : connectivity, [&](unsigned char* bytes) {
      std::int32_t* const values = reinterpret_cast<std::int32_t*>(bytes);
      for (std::size_t i = 0; i < points; ++i) values[i] = std::int32_t(i) + first;
    });
  out << "\n</AppendedData>\n</VTKFile>\n";
  f.commit();
}

void write_vtp(const std::string& path, std::size_t points, const VtpArray& positions, const std::vector<VtpArray>& arrays) {
  std::vector<VtpLayout> layouts;
  auto check_size = [points, &path](const VtpArray& a) {
    if (a.bytes.size() != points * std::size_t(a.layout.components) * a.layout.value_bytes)
      throw std::invalid_argument(path + ": array " + a.layout.name + " holds " + std::to_string(a.bytes.size()) +
                                  " bytes, not " + std::to_string(points) + " points' worth");
  };
  check_size(positions);
  for (const VtpArray& a : arrays) check_size(a), layouts.push_back(a.layout);
  std::vector<unsigned char> buffer;
  write_vtp(
      path, points, layouts, positions.layout,
      [&](std::size_t k, unsigned char* out) {
        const std::vector<unsigned char>& bytes = k < arrays.size() ? arrays[k].bytes : positions.bytes;
        std::copy(bytes.begin(), bytes.end(), out);
      },
      buffer);
}

void remove_particle_frames(const std::string& dir) {
  namespace fs = std::filesystem;
  std::error_code error;
  if (!fs::is_directory(dir, error)) return;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir)) {
    if (particle_frame_number(entry.path().filename().string()) >= 0) fs::remove(entry.path());
  }
  fs::remove(dir, error);  // only if empty
}

}  // namespace firn
