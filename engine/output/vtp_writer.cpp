#include "engine/output/vtp_writer.hpp"

#include <numeric>

namespace firn {

void write_vtp(const std::string& path, std::size_t points, const VtpArray& positions, const std::vector<VtpArray>& arrays) {
  // Verts: vertex i is point i (connectivity i, offsets i + 1), so viewers draw every point.
  std::vector<std::int32_t> connectivity(points), offsets(points);
  std::iota(connectivity.begin(), connectivity.end(), 0);
  std::iota(offsets.begin(), offsets.end(), 1);
  const VtpArray conn = vtp_array("connectivity", 1, connectivity), offs = vtp_array("offsets", 1, offsets);

  std::uint64_t offset = 0;
  std::string xml;
  auto declare = [&](const VtpArray& a, bool named) {
    xml += "<DataArray type=\"" + a.type + "\"" + (named ? " Name=\"" + a.name + "\"" : std::string()) +
           " NumberOfComponents=\"" + std::to_string(a.components) + "\" format=\"appended\" offset=\"" +
           std::to_string(offset) + "\"/>\n";
    offset += sizeof(std::uint64_t) + a.bytes.size();
  };
  xml += "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" "
         "header_type=\"UInt64\">\n<PolyData>\n<Piece NumberOfPoints=\"" + std::to_string(points) +
         "\" NumberOfVerts=\"" + std::to_string(points) +
         "\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n<PointData>\n";
  for (const VtpArray& a : arrays) declare(a, true);
  xml += "</PointData>\n<Points>\n";
  declare(positions, false);
  xml += "</Points>\n<Verts>\n";
  declare(conn, true);
  declare(offs, true);
  xml += "</Verts>\n</Piece>\n</PolyData>\n<AppendedData encoding=\"raw\">\n_";

  AtomicFile f(path);
  std::ofstream& out = f.stream();
  out << xml;
  auto append = [&](const VtpArray& a) {
    const std::uint64_t size = a.bytes.size();
    out.write(reinterpret_cast<const char*>(&size), sizeof size);
    out.write(reinterpret_cast<const char*>(a.bytes.data()), std::streamsize(a.bytes.size()));
  };
  for (const VtpArray& a : arrays) append(a);
  append(positions);
  append(conn);
  append(offs);
  out << "\n</AppendedData>\n</VTKFile>\n";
  f.commit();
}

}  // namespace firn
