#include "viz/engine_frame.hpp"

#include <type_traits>

#include "viz/collider_sdf.hpp"
#include "viz/color_field.hpp"

namespace firn::viz {
namespace {

template <class T>
void take_particles(const ParticleView<T>& pv, const std::string& color_by, std::vector<float>& field,
                    RenderFrame& r) {
  for (int d = 0; d < 3; ++d) r.positions.x[d] = pv.x[d];
  r.positions.doubles = std::is_same_v<T, double>;
  r.positions.count = pv.n;
  if (color_by != "material") {
    color_field_values(pv, color_by, field);
    r.field = field.data();
  }
}

}  // namespace

RenderFrame engine_frame(const FrameDescription& f, const std::string& color_by, std::vector<float>& field_storage) {
  RenderFrame r;
  r.frame = f.frame;
  r.time = f.time;
  if (f.particles_float) take_particles(*f.particles_float, color_by, field_storage, r);
  else take_particles(*f.particles_double, color_by, field_storage, r);
  r.materials = f.materials;
  if (f.colliders)
    for (const Collider<double>& c : *f.colliders) r.colliders.push_back(collider_sdf(c));
  return r;
}

}  // namespace firn::viz
