#include "viz/vtp_frame.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "engine/scene/scene_builder.hpp"
#include "engine/scene/scene_materials.hpp"
#include "viz/collider_sdf.hpp"
#include "viz/vtp_reader.hpp"

namespace firn::viz {

namespace {

const VtpArrayData& ids_of(const VtpFile& f, const std::string& path) {
  const auto id = f.arrays.find("id");
  if (id == f.arrays.end()) throw std::runtime_error(path + ": no 'id' array");
  return id->second;
}

}  // namespace

VtpRestPositions read_vtp_rest_positions(const std::string& first_frame_path) {
  const VtpFile f = read_vtp(first_frame_path);
  const VtpArrayData& ids = ids_of(f, first_frame_path);
  VtpRestPositions rest;
  const std::size_t count = ids.values.empty() ? 0 : std::size_t(*std::max_element(ids.values.begin(), ids.values.end())) + 1;
  for (auto& x : rest.x) x.assign(count, 0.0);
  rest.known.assign(count, false);
  for (std::size_t i = 0; i < f.points; ++i) {
    const std::size_t id = std::size_t(ids.values[i]);
    for (std::size_t d = 0; d < 3; ++d) rest.x[d][id] = f.positions.values[3 * i + d];
    rest.known[id] = true;
  }
  return rest;
}

VtpFrame::VtpFrame(const std::string& path, int frame, const SceneSpec& scene, const VtpRestPositions* rest)
    : frame_(frame), time_(std::min(scene.end_time, frame * scene.frame_interval)), scene_(scene) {
  const VtpFile f = read_vtp(path);
  const auto material = f.arrays.find("material");
  if (material == f.arrays.end()) throw std::runtime_error(path + ": no 'material' array");
  const SceneMaterials engine_materials(scene);  // the .vtp holds engine materials: a varied table's levels
  const int materials = int(engine_materials.engine().size());
  // Stable counting sort by material, so each material is one run of particles.
  std::vector<std::size_t> count(std::size_t(materials) + 1, 0);
  for (double m : material->second.values) {
    if (m < 0 || m >= materials) throw std::runtime_error(path + ": material index out of the scene's range");
    ++count[std::size_t(m) + 1];
  }
  for (int m = 0; m < materials; ++m) {
    count[std::size_t(m) + 1] += count[std::size_t(m)];
    materials_.push_back({count[std::size_t(m)], count[std::size_t(m) + 1], engine_materials.table_of(m)});
  }
  std::vector<std::size_t> order(f.points);
  for (std::size_t i = 0; i < f.points; ++i) order[count[std::size_t(material->second.values[i])]++] = i;

  for (int d = 0; d < 3; ++d) {
    x_[d].resize(f.points);
    for (std::size_t i = 0; i < f.points; ++i) x_[d][i] = f.positions.values[3 * order[i] + std::size_t(d)];
  }
  if (rest) {
    const VtpArrayData& ids = ids_of(f, path);
    for (int d = 0; d < 3; ++d) x0_[d] = x_[d];
    for (std::size_t i = 0; i < f.points; ++i) {
      const std::size_t id = std::size_t(ids.values[order[i]]);
      if (id < rest->known.size() && rest->known[id])
        for (int d = 0; d < 3; ++d) x0_[d][i] = rest->x[d][id];
    }
  }
  const double spacing = scene.config.dx / scene.per_axis();
  vol0_.assign(f.points, spacing * spacing * spacing);
  const std::string& by = scene.render.color_by;
  if (by == "material") return;
  // The .vtp arrays behind each colour field (engine/output/vtp_writer.hpp).
  const std::string name = by == "speed" ? "velocity" : by == "stress" ? "von_mises" : by;
  const auto a = f.arrays.find(name);
  field_.assign(f.points, 0.0f);
  if (a == f.arrays.end()) {
    if (by == "plastic_strain") return;  // no plastic material in this run: zero everywhere
    throw std::runtime_error(path + ": no '" + name + "' array for color_by = " + by);
  }
  for (std::size_t i = 0; i < f.points; ++i) {
    const double* v = &a->second.values[order[i] * std::size_t(a->second.components)];
    field_[i] = float(by == "speed" ? std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) : v[0]);
  }
}

RenderFrame VtpFrame::render_frame() const {
  RenderFrame r;
  r.frame = frame_;
  r.time = time_;
  for (int d = 0; d < 3; ++d) r.positions.x[d] = x_[d].data();
  r.positions.doubles = true;
  r.positions.count = x_[0].size();
  r.materials = materials_;
  r.field = field_.empty() ? nullptr : field_.data();
  for (const Collider<double>& c : scene_colliders_at(scene_, time_)) r.colliders.push_back(collider_solid(c));
  return r;
}

ParticleView<double> VtpFrame::particle_view() const {
  ParticleView<double> v{};
  for (int d = 0; d < 3; ++d) {
    v.x[d] = const_cast<double*>(x_[d].data());
    v.x0[d] = x0_[d].empty() ? nullptr : const_cast<double*>(x0_[d].data());
  }
  v.vol0 = const_cast<double*>(vol0_.data());
  v.n = x_[0].size();
  return v;
}

}  // namespace firn::viz
