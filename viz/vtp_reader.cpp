#include "viz/vtp_reader.hpp"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace firn::viz {
namespace {

std::string attribute(const std::string& tag, const std::string& name) {
  const std::string key = " " + name + "=\"";
  const std::size_t at = tag.find(key);
  if (at == std::string::npos) return "";
  const std::size_t begin = at + key.size();
  return tag.substr(begin, tag.find('"', begin) - begin);
}

template <class S>
void convert(const unsigned char* bytes, std::size_t count, std::vector<double>& out) {
  out.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    S v;
    std::memcpy(&v, bytes + i * sizeof(S), sizeof(S));
    out[i] = double(v);
  }
}

}  // namespace

VtpFile read_vtp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot open " + path);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  auto fail = [&](const std::string& why) { return std::runtime_error(path + ": " + why); };
  const std::size_t appended = text.find("<AppendedData encoding=\"raw\">");
  if (appended == std::string::npos) throw fail("no raw appended data (not written by firn?)");
  const std::size_t data = text.find('_', appended);
  if (data == std::string::npos) throw fail("appended data has no '_' marker");
  const std::size_t base = data + 1;
  const std::string header = text.substr(0, appended);

  VtpFile f;
  const std::string piece = header.substr(header.find("<Piece"));
  f.points = std::stoul(attribute(piece.substr(0, piece.find('>')), "NumberOfPoints"));
  const std::size_t points_section = header.find("<Points>");
  for (std::size_t at = header.find("<DataArray"); at != std::string::npos; at = header.find("<DataArray", at + 1)) {
    const std::string tag = header.substr(at, header.find('>', at) - at);
    const std::string type = attribute(tag, "type"), name = attribute(tag, "Name");
    const std::size_t offset = base + std::stoull(attribute(tag, "offset"));
    if (name == "connectivity" || name == "offsets") continue;
    if (offset + sizeof(std::uint64_t) > text.size()) throw fail("array '" + name + "' lies past the end");
    std::uint64_t size;
    std::memcpy(&size, text.data() + offset, sizeof size);
    if (offset + sizeof size + size > text.size()) throw fail("array '" + name + "' is truncated");
    const auto* bytes = reinterpret_cast<const unsigned char*>(text.data() + offset + sizeof size);
    VtpArrayData a;
    a.components = std::stoi(attribute(tag, "NumberOfComponents"));
    if (type == "Float32") convert<float>(bytes, size / 4, a.values);
    else if (type == "Float64") convert<double>(bytes, size / 8, a.values);
    else if (type == "Int32") convert<std::int32_t>(bytes, size / 4, a.values);
    else if (type == "UInt32") convert<std::uint32_t>(bytes, size / 4, a.values);
    else throw fail("unsupported array type " + type);
    if (a.values.size() != f.points * std::size_t(a.components)) throw fail("array '" + name + "' has the wrong size");
    if (at > points_section && name.empty()) f.positions = std::move(a);
    else f.arrays[name] = std::move(a);
  }
  if (f.positions.components != 3 || f.positions.values.size() != 3 * f.points) throw fail("no points");
  return f;
}

}  // namespace firn::viz
