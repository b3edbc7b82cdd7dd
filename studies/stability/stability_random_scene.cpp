#include "studies/stability/stability_random_scene.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

#include "engine/splitmix64.hpp"

namespace firn::study {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Draws from a SplitMix64 stream (engine/splitmix64.hpp): the same on every machine.
class Random {
 public:
  explicit Random(std::uint64_t seed) : rng_{seed} {}
  std::uint64_t next() { return rng_.next(); }
  double uniform(double lo, double hi) { return lo + (hi - lo) * rng_.uniform(); }
  double log_uniform(double lo, double hi) { return std::exp(uniform(std::log(lo), std::log(hi))); }
  int integer(int lo, int hi) { return lo + int(next() % std::uint64_t(hi - lo + 1)); }  // [lo, hi]
  bool chance(double p) { return uniform(0, 1) < p; }
  std::array<double, 3> direction() {  // uniform on the unit sphere
    const double z = uniform(-1, 1), phi = uniform(0, 2 * kPi), r = std::sqrt(1 - z * z);
    return {r * std::cos(phi), r * std::sin(phi), z};
  }

 private:
  SplitMix64 rng_;
};

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

std::string vec(const std::array<double, 3>& v) { return "[" + num(v[0]) + ", " + num(v[1]) + ", " + num(v[2]) + "]"; }

struct Body {
  std::string shape;
  std::array<double, 3> center;
  double radius;         // bounding sphere, used to keep bodies apart
  double volume;         // m^3
  std::string geometry;  // the shape's keys
};

struct Material {
  std::string model, table;
  double density, E, nu;
  double wave_speed() const {  // sqrt((K + 4G/3) / rho) = sqrt(E (1 - nu) / ((1 + nu)(1 - 2 nu) rho))
    return std::sqrt(E * (1 - nu) / ((1 + nu) * (1 - 2 * nu) * density));
  }
};

Material random_material(Random& r) {
  static const char* models[] = {"neo_hookean", "fixed_corotated", "mooney_rivlin", "hyperelastic_plastic",
                                 "snow_stomakhin"};
  Material m;
  m.model = models[r.integer(0, 4)];
  const std::string& model = m.model;
  const bool snow = model == "hyperelastic_plastic" || model == "snow_stomakhin";
  m.density = snow ? r.uniform(200, 600) : r.uniform(200, 2000);
  m.E = snow ? r.log_uniform(3e4, 3e5) : r.log_uniform(1e4, 1e7);
  m.nu = r.uniform(0, 0.49);
  m.table = "model = \"" + model + "\"\ndensity = " + num(m.density) + "\nE = " + num(m.E) + "\nnu = " + num(m.nu) + "\n";
  const double G = m.E / (2 * (1 + m.nu));
  if (model == "mooney_rivlin") m.table += "G2 = " + num(r.uniform(0, 0.5) * G) + "\n";
  if (model == "hyperelastic_plastic")
    m.table += "sigma_y0 = " + num(r.log_uniform(50, 1e4)) + "\nK_h = " + num(r.uniform(0, 20)) +
               "\nn = " + num(r.uniform(0.02, 1)) + "\n";
  if (model == "snow_stomakhin")
    m.table += "theta_c = " + num(r.uniform(0.01, 0.05)) + "\ntheta_s = " + num(r.uniform(0.0025, 0.01)) +
               "\nxi = " + num(r.uniform(5, 15)) + "\n";
  return m;
}

// A shape 3-12 cells across; the centre is placed later.
Body random_shape(Random& r, double dx) {
  Body b;
  const int kind = r.integer(0, 2);
  if (kind == 0) {
    const double radius = r.uniform(2, 6) * dx;
    b.shape = "sphere";
    b.radius = radius;
    b.volume = 4.0 / 3 * kPi * radius * radius * radius;
  } else if (kind == 1) {
    const std::array<double, 3> half = {r.uniform(1.5, 5) * dx, r.uniform(1.5, 5) * dx, r.uniform(1.5, 5) * dx};
    b.shape = "box";
    b.radius = std::sqrt(half[0] * half[0] + half[1] * half[1] + half[2] * half[2]);
    b.volume = 8 * half[0] * half[1] * half[2];
    b.geometry = vec(half);  // resolved into min/max once the centre is known
  } else {
    const double radius = r.uniform(1.5, 5) * dx, length = r.uniform(3, 10) * dx;
    b.shape = "cylinder";
    b.radius = std::hypot(radius, 0.5 * length);
    b.volume = kPi * radius * radius * length;
    b.geometry = "radius = " + num(radius) + "\nlength = " + num(length) + "\naxis = \"" + "xyz"[r.integer(0, 2)] + "\"\n";
  }
  return b;
}

std::string body_geometry(const Body& b) {
  if (b.shape == "sphere") return "center = " + vec(b.center) + "\nradius = " + num(b.radius) + "\n";
  if (b.shape == "cylinder") return "center = " + vec(b.center) + "\n" + b.geometry;
  // box: geometry holds the half extents
  double half[3];
  std::sscanf(b.geometry.c_str(), "[%lf, %lf, %lf]", &half[0], &half[1], &half[2]);
  return "min = " + vec({b.center[0] - half[0], b.center[1] - half[1], b.center[2] - half[2]}) + "\nmax = " +
         vec({b.center[0] + half[0], b.center[1] + half[1], b.center[2] + half[2]}) + "\n";
}

}  // namespace

RandomScene random_scene(std::uint64_t seed, int index) {
  Random r(seed * 0x100000001b3ull + std::uint64_t(index) * 0x9e3779b97f4a7c15ull + 1);
  RandomScene out;
  const double dx = r.uniform(0.0025, 0.005);
  const int cells = r.integer(20, 32);
  const double size = cells * dx;
  const int ppc = r.chance(0.5) ? 1 : 8;
  const double cfl = r.uniform(0.2, 1.0);
  static const char* transfers[] = {"apic", "pic", "flip"};
  const std::string transfer = transfers[r.integer(0, 2)];
  const std::string shape = r.chance(0.5) ? "quadratic" : "cubic";
  const std::string precision = r.chance(0.125) ? "double" : "float";
  std::array<double, 3> gravity = {0, -9.81, 0};
  if (r.chance(0.25)) {
    const auto d = r.direction();
    const double g = r.uniform(0, 20);
    gravity = {g * d[0], g * d[1], g * d[2]};
  }

  // Bodies: kept 4 cells inside the domain (the walls' band is 3) and apart from each other, the
  // particle count capped by shrinking the later ones away.
  const double margin = 4 * dx;
  const double cell_volume = dx * dx * dx;
  std::vector<Body> bodies;
  const int wanted = r.integer(1, 3);
  double particles = 0;
  for (int attempt = 0; attempt < 40 && int(bodies.size()) < wanted; ++attempt) {
    Body b = random_shape(r, dx);
    if (particles + b.volume / cell_volume * ppc > 6000) continue;
    const double lo = margin + b.radius, hi = size - margin - b.radius;
    if (hi <= lo) continue;
    b.center = {r.uniform(lo, hi), r.uniform(lo, hi), r.uniform(lo, hi)};
    bool apart = true;
    for (const Body& o : bodies) {
      double d2 = 0;
      for (int d = 0; d < 3; ++d) d2 += (b.center[d] - o.center[d]) * (b.center[d] - o.center[d]);
      apart = apart && std::sqrt(d2) > b.radius + o.radius + dx;
    }
    if (!apart) continue;
    particles += b.volume / cell_volume * ppc;
    bodies.push_back(b);
  }
  if (bodies.empty()) {  // the fallback: one small sphere in the middle
    Body b;
    b.shape = "sphere";
    b.radius = 2 * dx;
    b.volume = 4.0 / 3 * kPi * b.radius * b.radius * b.radius;
    b.center = {size / 2, size / 2, size / 2};
    particles = b.volume / cell_volume * ppc;
    bodies.push_back(b);
  }

  std::string materials, body_tables;
  double max_wave = 0, max_speed = 0;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const Material m = random_material(r);
    max_wave = std::max(max_wave, m.wave_speed());
    const std::string name = "m" + std::to_string(i);
    materials += "[materials." + name + "]\n" + m.table + "\n";
    const double speed = r.uniform(0, 20), spin = r.chance(0.5) ? r.uniform(0, 50) : 0.0;
    const auto dir = r.direction(), axis = r.direction();
    max_speed = std::max(max_speed, speed + spin * bodies[i].radius);
    body_tables += "[[bodies]]\nname = \"body" + std::to_string(i) + "\"\nmaterial = \"" + name + "\"\nshape = \"" +
                   bodies[i].shape + "\"\n" + body_geometry(bodies[i]) + "velocity = " +
                   vec({speed * dir[0], speed * dir[1], speed * dir[2]}) + "\nangular_velocity = " +
                   vec({spin * axis[0], spin * axis[1], spin * axis[2]}) + "\n\n";
    out.summary += (i ? ", " : "") + bodies[i].shape + " of " + m.model;
  }

  std::string colliders;
  static const char* boundaries[] = {"sticky", "slip", "separate"};
  const int collider_count = r.integer(0, 2);
  for (int c = 0; c < collider_count; ++c) {
    const int kind = r.integer(0, 3);
    std::string t = "[[colliders]]\nname = \"c" + std::to_string(c) + "\"\n";
    if (kind == 0) {
      t += "shape = \"plane\"\npoint = " + vec({0, margin, 0}) + "\nnormal = [0, 1, 0]\n";
      out.summary += ", floor";
    } else if (kind == 1) {
      const auto n = r.direction();
      t += "shape = \"plane\"\npoint = " + vec({size / 2 - n[0] * size * 0.45, size / 2 - n[1] * size * 0.45,
                                                size / 2 - n[2] * size * 0.45}) +
           "\nnormal = " + vec(n) + "\n";
      out.summary += ", tilted plane";
    } else if (kind == 2) {
      const std::array<double, 3> c0 = {r.uniform(0.2, 0.7) * size, r.uniform(0.2, 0.7) * size, r.uniform(0.2, 0.7) * size};
      const double side = r.uniform(2, 5) * dx;
      t += "shape = \"box\"\nmin = " + vec(c0) + "\nmax = " + vec({c0[0] + side, c0[1] + side, c0[2] + side}) + "\n";
      out.summary += ", box";
    } else {
      t += "shape = \"cylinder\"\ncenter = " +
           vec({r.uniform(0.3, 0.7) * size, r.uniform(0.3, 0.7) * size, r.uniform(0.3, 0.7) * size}) +
           "\nradius = " + num(r.uniform(1.5, 4) * dx) + "\nlength = " + num(size) + "\naxis = \"" + "xyz"[r.integer(0, 2)] +
           "\"\nangular_velocity = " + vec({0, 0, r.uniform(-50, 50)}) + "\n";
      out.summary += ", spinning cylinder";
    }
    t += "boundary = \"" + std::string(boundaries[r.integer(0, 2)]) + "\"\nfriction = " + num(r.uniform(0, 1)) + "\n\n";
    colliders += t;
  }

  // The end time: 50-300 steps of the first time step (later ones shrink as the bodies speed up).
  const long steps = r.integer(50, 300);
  const double dt = std::min(1e-3, cfl * dx / (max_wave + max_speed));
  const double end_time = double(steps) * dt;
  out.particles_estimate = long(particles);
  out.steps_estimate = steps;
  out.toml = "# firn study stability: random scene " + std::to_string(index) + " of seed " + std::to_string(seed) +
             "\n[simulation]\ndomain_min = [0, 0, 0]\ndomain_max = " + vec({size, size, size}) + "\ndx = " + num(dx) +
             "\nparticles_per_cell = " + std::to_string(ppc) + "\nend_time = " + num(end_time) +
             "\nframe_interval = " + num(end_time / 3) + "\ncfl = " + num(cfl) + "\ngravity = " + vec(gravity) +
             "\ntransfer = \"" + transfer + "\"\nshape = \"" + shape + "\"\nprecision = \"" + precision + "\"\n\n" +
             materials + body_tables + colliders;
  return out;
}

}  // namespace firn::study
