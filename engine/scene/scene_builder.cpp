#include "engine/scene/scene_builder.hpp"

namespace firn {
namespace {

// SplitMix64 (Steele, Lea and Flood 2014): a portable, seedable stream, so jittered scenes are the
// same on every platform (std::uniform_real_distribution is implementation-defined).
struct SplitMix64 {
  std::uint64_t state;
  std::uint64_t next() {
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  double uniform() { return double(next() >> 11) * 0x1.0p-53; }  // [0, 1)
};

}  // namespace

void fill_body(const SceneSpec& scene, std::size_t index, std::vector<Point>& positions, std::vector<Point>& velocities) {
  const BodySpec& body = scene.bodies[index];
  Point lo, hi;
  body.shape.bounds(lo, hi);
  positions = fill_lattice(scene.config.domain_min, scene.config.dx, scene.per_axis(), lo, hi, [&](const Point& p) {
    if (!body.shape.contains(p)) return false;
    for (std::size_t e = 0; e < index; ++e)
      if (scene.bodies[e].shape.contains(p)) return false;
    return true;
  });
  if (positions.empty())
    throw SceneError(body.location + ": body '" + body.name +
                     "' has no particles (smaller than the particle spacing, or inside earlier bodies)");
  if (body.jitter > 0) {
    SplitMix64 rng{body.seed};
    const double amplitude = body.jitter * scene.config.dx / scene.per_axis();
    for (Point& p : positions)
      for (int d = 0; d < 3; ++d) p[d] += amplitude * (rng.uniform() - 0.5);
  }
  Point c = {0, 0, 0};
  for (const Point& p : positions)
    for (int d = 0; d < 3; ++d) c[d] += p[d] / double(positions.size());
  const Point& w = body.angular_velocity;
  velocities.resize(positions.size());
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const Point r = {positions[i][0] - c[0], positions[i][1] - c[1], positions[i][2] - c[2]};
    velocities[i] = {body.velocity[0] + w[1] * r[2] - w[2] * r[1], body.velocity[1] + w[2] * r[0] - w[0] * r[2],
                     body.velocity[2] + w[0] * r[1] - w[1] * r[0]};
  }
}

}  // namespace firn
