#include "engine/scene/checkpoint.hpp"

#include <algorithm>
#include <cinttypes>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include "engine/output/atomic_file.hpp"
#include "engine/scene/units.hpp"
#include "engine/version.hpp"

namespace firn {
namespace {

constexpr char kMagic[8] = {'F', 'I', 'R', 'N', 'C', 'K', 'P', 'T'};
constexpr std::uint32_t kFormat = 2;  // 2: the binning's walk breaks (ParticleBinning::needs_reorder)

std::string hex(std::uint64_t v) {
  char buf[20];
  std::snprintf(buf, sizeof buf, "%016" PRIx64, v);
  return buf;
}

}  // namespace

double checkpoint_interval(const std::string& text) {
  double every = 0;
  try {
    every = parse_quantity(text, Quantity::time);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument("--checkpoint-every " + text + ": " + e.what());
  }
  if (!(every > 0)) throw std::invalid_argument("--checkpoint-every " + text + ": not a positive time");
  return every;
}

std::string checkpoint_path(const std::string& out_dir) { return out_dir + "/checkpoint.firn"; }

std::uint64_t text_digest(const std::string& text) {
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : text) h = (h ^ c) * 1099511628211ull;
  return h;
}

void write_checkpoint(const std::string& path, const std::string& resolved_toml, const RunCheckpoint& c) {
  StateWriter out;
  out.value(kMagic);
  out.value(kFormat);
  out.text(firn_version());
  out.value(text_digest(resolved_toml));
  out.value(std::int32_t(c.next_frame));
  out.text(c.metrics);
  out.value(c.initial_energy);
  out.value(c.particle_steps);
  out.value(c.step_seconds);
  out.text(c.engine_state);
  out.value(text_digest(out.bytes()));  // the whole file's, against corruption
  write_file_atomically(path, out.bytes(), true);
}

RunCheckpoint read_checkpoint(const std::string& path, const std::string& resolved_toml) {
  std::string data;
  try {
    data = read_text_file(path);
  } catch (const std::runtime_error&) {
    throw CheckpointError(path + ": no checkpoint (the run was not interrupted and not started with "
                                 "--checkpoint-every, or stopped before its first)");
  }
  try {
    StateReader::expect(data.size() >= sizeof(std::uint64_t), "not a firn checkpoint");
    std::uint64_t checksum;
    std::memcpy(&checksum, data.data() + data.size() - sizeof checksum, sizeof checksum);
    StateReader in(data.data(), data.size() - sizeof checksum);
    char magic[8];
    in.read(magic);
    StateReader::expect(std::equal(magic, magic + 8, kMagic), "not a firn checkpoint");
    const auto format = in.value<std::uint32_t>();
    StateReader::expect(format == kFormat, "checkpoint format " + std::to_string(format) + ", this firn reads " +
                                               std::to_string(kFormat));
    const std::string version = in.text();
    StateReader::expect(version == firn_version(), "written by firn " + version + ", this is firn " + firn_version() +
                                                        " (resume with the firn that started the run)");
    const auto digest = in.value<std::uint64_t>();
    StateReader::expect(digest == text_digest(resolved_toml),
                        "written for another scene (digest " + hex(digest) + ", the run's scene.resolved.toml has " +
                            hex(text_digest(resolved_toml)) + ")");
    RunCheckpoint c;
    c.next_frame = in.value<std::int32_t>();
    c.metrics = in.text();
    in.read(c.initial_energy);
    in.read(c.particle_steps);
    in.read(c.step_seconds);
    c.engine_state = in.text();
    StateReader::expect(in.at_end() && c.next_frame >= 1 &&
                            checksum == text_digest(data.substr(0, data.size() - sizeof checksum)),
                        "checkpoint is damaged (its checksum does not match)");
    return c;
  } catch (const CheckpointError& e) {
    throw CheckpointError(path + ": " + e.what());
  }
}

}  // namespace firn
