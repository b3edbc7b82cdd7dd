// The scene's own metrics.csv columns, after the standard ones (DESIGN.md section 5; issue 5,
// "Metrics"). Each scene pays only for what it has:
//   every collider NAME: NAME_fx, NAME_fy, NAME_fz (force on it, N) and NAME_tx, NAME_ty, NAME_tz
//     (torque about its centre, N m), averaged over the frame;
//   a [tire]: traction (its force along +x, the direction it rolls), vertical_load (its force along
//     +y), axle_torque (about +z), motion_resistance_coefficient (-traction / W: the snow's force
//     against the rolling direction over the wheel load W, the axle's `load` on a loaded axle and
//     vertical_load on a fixed one; empty while W <= 0; Wong, Theory of Ground Vehicles, the
//     coefficient of motion resistance), slip_ratio ((tread speed - ground speed) / ground speed, 0
//     without a conveyor; a free spin's tread speed at the frame's end), axle_height, sinkage (with
//     a conveyor: the undisturbed snow surface ground + depth minus the tread's lowest point
//     axle_height - radius; the depth of the wheel's bottom below the surface it rolls into),
//     peak_pressure (the footprint's peak, Pa, when written; a rubber tire: peak_tread_stress, the
//     tread stress map's peak, engine/output/tread_stress.hpp), contact_length (a rubber tire on a
//     road, the first plane among [[colliders]]: the length along x of the tread particles that
//     touch the road, engine/output/contact_patch.hpp),
//     displaced (particles farther than metrics.displaced_distance from where the undisturbed
//     ground would have carried them: x0 - U t e_x; the thesis' Table 5.1) and accumulated
//     (particles inside the tread's outer radius and width: snow carried in the tread, Figure 5.6),
//     both over snow only (a rubber tire's particles left out);
//   a [conveyor]: injected and removed (particles, since the start);
//   metrics.fragments: fragments and largest_fragment (engine/fragments.hpp), the particles' connected
//     clusters of at least metrics.fragment_min_particles, linked closer than fragment_link_cells dx.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "engine/scene/conveyor.hpp"
#include "engine/fragments.hpp"
#include "engine/output/contact_patch.hpp"
#include "engine/output/footprint_writer.hpp"
#include "engine/output/tread_stress.hpp"
#include "engine/scene/scene.hpp"
#include "engine/scene/scene_builder.hpp"
#include "engine/simulation.hpp"
#include "kernels/hd.hpp"
#include "kernels/particle_attributes.hpp"
#include "kernels/particle_ranges.hpp"

namespace firn {

// The tire's snow counts as the term of a parallel_reduce: particles displaced farther than
// sqrt(limit2) from where the ground would have carried them (x0 - shift e_x), and particles inside
// the tread (within sqrt(radius2) of the axle, half_width of its mid-plane).
struct SnowCounts {
  std::size_t displaced = 0, accumulated = 0;
};

template <class T>
struct SnowCountTerm {
  ParticleView<T> pv;
  T cx, cy, cz, radius2, half_width, shift, limit2;
  ParticleRanges tire;  // a rubber tire's particles (its tread's and its carcass's), which are not snow

  FIRN_HD void operator()(std::size_t p, SnowCounts& acc) const {
    if (tire.holds(p)) return;
    const T dx = pv.x[0][p] - (pv.x0[0][p] - shift), dy = pv.x[1][p] - pv.x0[1][p], dz = pv.x[2][p] - pv.x0[2][p];
    acc.displaced += dx * dx + dy * dy + dz * dz > limit2;
    const T rx = pv.x[0][p] - cx, ry = pv.x[1][p] - cy;
    acc.accumulated += rx * rx + ry * ry <= radius2 && std::fabs(pv.x[2][p] - cz) <= half_width;
  }
};

struct MergeSnowCounts {
  FIRN_HD void operator()(SnowCounts& a, const SnowCounts& b) const {
    a.displaced += b.displaced;
    a.accumulated += b.accumulated;
  }
};

template <class T, class Backend>
class SceneMetrics {
 public:
  SceneMetrics(const SceneSpec& scene, const BuiltScene& built, const Conveyor* conveyor)
      : scene_(scene), built_(built), conveyor_(conveyor) {
    for (const ColliderSpec& c : scene.colliders) names_.push_back(c.name);
    if (built.tire >= 0) names_.push_back("tire");
    if (built.ground >= 0) names_.push_back("ground");
  }

  // Starts the footprint map when the scene writes one.
  void prepare(Simulation<T, Backend>& sim) const {
    if (writes_footprint()) sim.enable_footprint(built_.tire);
  }
  // The footprint is the rigid tire's contact pressure; a rubber tire's contact is with particles.
  bool writes_footprint() const { return built_.tire >= 0 && scene_.metrics.footprint && !scene_.tire->rubber; }
  bool writes_tread_stress() const { return built_.tire >= 0 && scene_.metrics.footprint && scene_.tire->rubber; }
  // A rubber tire on a road plane: the length of the tread's contact patch on the road.
  bool measures_road_contact() const { return writes_tread_stress() && built_.road >= 0; }
  // The folder of the per-frame map: footprint (a rigid tire's contact pressure), tread_stress (a
  // rubber tire's tread stress), or "" when the scene writes none.
  std::string map_dir() const { return writes_footprint() ? "footprint" : writes_tread_stress() ? "tread_stress" : ""; }

  // ",NAME,..." to append to the standard header.
  std::string header() const {
    std::string h;
    for (const std::string& n : names_)
      for (const char* c : {"_fx", "_fy", "_fz", "_tx", "_ty", "_tz"}) h += "," + n + c;
    if (built_.tire >= 0) {
      h += ",traction,vertical_load,axle_torque,motion_resistance_coefficient,slip_ratio,axle_height";
      if (conveyor_) h += ",sinkage";
      if (writes_footprint()) h += ",peak_pressure";
      if (writes_tread_stress()) h += ",peak_tread_stress";
      if (measures_road_contact()) h += ",contact_length";
      h += ",displaced,accumulated";
    }
    if (conveyor_) h += ",injected,removed";
    if (scene_.metrics.fragments) h += ",fragments,largest_fragment";
    return h;
  }

  // ",VALUE,..." for the frame that ends now; writes the frame's map (map_dir()) under `map_stem`
  // (when the scene has them) and restarts the frame's averages.
  std::string row(Simulation<T, Backend>& sim, const std::string& map_stem) {
    std::string r;
    for (std::size_t c = 0; c < sim.collider_count(); ++c) {
      ColliderBody& b = sim.collider(int(c));
      const double inv = b.impulse_time > 0 ? 1 / b.impulse_time : 0;
      for (double v : b.impulse) r += number(v * inv);
      for (double v : b.angular_impulse) r += number(v * inv);
    }
    if (built_.tire >= 0) {
      const ColliderBody& tire = sim.collider(built_.tire);
      const TireSpec& t = *scene_.tire;
      const double inv = tire.impulse_time > 0 ? 1 / tire.impulse_time : 0;
      const double ground_speed = conveyor_ ? conveyor_->spec().speed : 0;
      const double traction = tire.impulse[0] * inv, vertical = tire.impulse[1] * inv;
      r += number(traction) + number(vertical) + number(tire.angular_impulse[2] * inv);
      const double wheel_load = t.loaded ? t.load : vertical;
      r += wheel_load > 0 ? number(-traction / wheel_load) : ",";
      const double tread_speed = t.free_spin ? -tire.collider.angular_velocity[2] * t.radius : t.speed;
      r += number(ground_speed > 0 ? (tread_speed - ground_speed) / ground_speed : 0);
      const double bottom = tire.collider.center[1] - t.radius;
      r += number(tire.collider.center[1]);
      if (conveyor_) r += number(conveyor_->spec().ground + conveyor_->spec().depth - bottom);
      if (writes_footprint()) {
        // The grid columns within a radius of the axle along x and two cells past the tread's edges.
        const FootprintWindow window{tire.collider.center[0], tire.collider.center[2], t.radius,
                                     0.5 * t.width + 2 * scene_.config.dx};
        char title[128];
        std::snprintf(title, sizeof title, "%s tread, t = %.1f ms, contact pressure averaged over the frame",
                      t.tread.c_str(), 1e3 * sim.time());
        r += number(write_footprint(map_stem, sim.footprint(), window, tire.collider, title));
        sim.footprint().reset();
      }
      if (writes_tread_stress()) r += number(write_tread_stress(sim, map_stem));
      if (measures_road_contact()) {
        const std::pair<std::size_t, std::size_t> tread = tread_particles(sim);
        r += number(contact_patch_length(sim.particles(), tread.first, tread.second, sim.collider(built_.road).collider,
                                         scene_.config.dx / scene_.per_axis()));
      }
      const SnowCounts n = count_snow(sim, ground_speed);
      r += number(double(n.displaced)) + number(double(n.accumulated));
    }
    if (conveyor_) r += number(double(conveyor_->injected())) + number(double(conveyor_->removed()));
    if (scene_.metrics.fragments) {
      const FragmentCount f = count_particle_fragments(sim);
      r += number(double(f.fragments)) + number(double(f.largest));
    }
    for (std::size_t c = 0; c < sim.collider_count(); ++c) sim.collider(int(c)).reset_impulse();
    return r;
  }

 private:
  FragmentCount count_particle_fragments(Simulation<T, Backend>& sim) const {
    const ParticleView<T> pv = sim.particles();
    std::vector<std::array<double, 3>> x(pv.n);
    for (std::size_t p = 0; p < pv.n; ++p)
      for (int d = 0; d < 3; ++d) x[p][d] = double(pv.x[d][p]);
    return count_fragments(x, scene_.metrics.fragment_link_cells * scene_.config.dx,
                           std::size_t(scene_.metrics.fragment_min_particles));
  }

  // The rubber tire's tread stress (engine/output/tread_stress.hpp) with the tread's outline at the
  // rim's pose; returns its peak.
  double write_tread_stress(Simulation<T, Backend>& sim, const std::string& stem) const {
    const TireSpec& t = *scene_.tire;
    const Collider<double>& rim = sim.collider(built_.tire).collider;
    Collider<double> solid = tire_solid(t);
    for (int d = 0; d < 3; ++d) solid.center[d] = rim.center[d];
    for (int i = 0; i < 9; ++i) solid.rotation[i] = rim.rotation[i];
    const std::pair<std::size_t, std::size_t> tread = tread_particles(sim);
    const double dx = scene_.config.dx;
    const FootprintField f =
        tread_stress_field(sim.particles(), tread.first, tread.second, solid, t.radius - t.tread_depth,
                           0.5 * t.width + 2 * dx, dx);
    FootprintFigureSpec spec;
    spec.axle_x = rim.center[0], spec.axle_z = rim.center[2];
    char title[128];
    std::snprintf(title, sizeof title, "%s tread, t = %.1f ms, von Mises stress of the tread below the axle",
                  t.tread.c_str(), 1e3 * sim.time());
    spec.title = title;
    spec.patch = kTreadStressPatch;
    spec.empty = kTreadStressEmpty;
    spec.tread = tread_cover(solid);
    return write_map(stem, f, spec);
  }

  // The particle range [first, second) of the rubber tire's tread (and the parts of its `material`).
  std::pair<std::size_t, std::size_t> tread_particles(Simulation<T, Backend>& sim) const {
    return {sim.material_range(built_.rubber.first).begin,
            sim.material_range(built_.rubber.first + built_.rubber.second - 1).end};
  }

  SnowCounts count_snow(Simulation<T, Backend>& sim, double ground_speed) const {
    const ParticleView<T> pv = sim.particles();
    const Collider<double>& c = sim.collider(built_.tire).collider;
    const T cx = T(c.center[0]), cy = T(c.center[1]), cz = T(c.center[2]);
    const T radius2 = T(scene_.tire->radius * scene_.tire->radius), half_width = T(0.5 * scene_.tire->width);
    const T shift = T(ground_speed * sim.time());
    const T limit2 = T(scene_.metrics.displaced_distance * scene_.metrics.displaced_distance);
    ParticleRanges tire;
    for (const std::pair<int, int>& t : {built_.rubber, built_.carcass, built_.sidewall})
      if (t.second > 0) {
        tire.begin[tire.count] = sim.material_range(t.first).begin;
        tire.end[tire.count++] = sim.material_range(t.first + t.second - 1).end;
      }
    return sim.backend().parallel_reduce(
        "metrics.snow", pv.n, SnowCounts{},
        SnowCountTerm<T>{pv, cx, cy, cz, radius2, half_width, shift, limit2, tire}, MergeSnowCounts{});
  }

  static std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, ",%.9g", v);
    return buf;
  }

  const SceneSpec& scene_;
  BuiltScene built_;
  const Conveyor* conveyor_;
  std::vector<std::string> names_;
};

}  // namespace firn
