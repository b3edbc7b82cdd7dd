// The conveyor snow bed at run time (issue 5, "Conveyor snow bed"; the scene keys are in
// engine/scene/scene.hpp, ConveyorSpec). The bed is a box of the particle lattice carried by the
// ground at velocity (-U, 0, 0). Lattice column j (x_j = domain_min.x + (j + 1/2) h at t = 0)
// is at x_j - U t at time t; the columns that start upstream of the inflow are injected, with the
// ground's velocity and F = I, at the step where they cross it, so the bed stays one lattice.
// Particles beyond the outflow, or within `kMargin` cells of the domain's boundary, are removed.
// Every particle's reference position x0 is where the undisturbed ground carried it from at t = 0
// (injected particles: x_j), so x0 - U t e_x is where it would be if nothing had disturbed it.
#pragma once

#include <cmath>
#include <vector>

#include "engine/particle_fill.hpp"
#include "engine/scene/scene.hpp"
#include "engine/scene/scene_materials.hpp"
#include "engine/simulation.hpp"
#include "engine/state_stream.hpp"
#include "kernels/hd.hpp"
#include "kernels/particle_attributes.hpp"

namespace firn {

class Conveyor {
 public:
  static constexpr double kMargin = 4;  // cells

  Conveyor(const SceneSpec& scene, const ConveyorSpec& spec)
      : spec_(spec), materials_(scene), origin_(scene.config.domain_min), dx_(scene.config.dx), per_axis_(scene.per_axis()),
        domain_min_(scene.config.domain_min), domain_max_(scene.config.domain_max),
        volume_(std::pow(scene.config.dx / scene.per_axis(), 3)) {
    const double h = dx_ / per_axis_;
    // The first column at or beyond the inflow: fill_lattice takes x < inflow for the initial bed.
    next_column_ = long(std::ceil((spec_.inflow - origin_[0]) / h - 0.5 - 1e-9));
  }

  // The bed at t = 0: the lattice sites of [outflow, inflow) x [ground, ground + depth) x [z_min, z_max).
  std::vector<Point> initial_bed() const { return columns(spec_.outflow, spec_.inflow); }

  // Before a step that starts at time t: removes what left and injects the columns that crossed
  // the inflow by time t (counted in removed() and injected()).
  template <class T, class Backend>
  void update(Simulation<T, Backend>& sim, double t) {
    const T outflow = T(spec_.outflow), margin = T(kMargin * dx_);
    const T lo[3] = {T(domain_min_[0]) + margin, T(domain_min_[1]) + margin, T(domain_min_[2]) + margin};
    const T hi[3] = {T(domain_max_[0]) - margin, T(domain_max_[1]) - margin, T(domain_max_[2]) - margin};
    removed_ += long(sim.remove_particles([=] FIRN_HD_LAMBDA(const ParticleView<T>& pv, std::size_t p) {
      // Bitwise, not short-circuit: no branch, so the count over all particles vectorises.
      bool out = pv.x[0][p] < outflow;
      for (int d = 0; d < 3; ++d) out = out | (pv.x[d][p] < lo[d]) | (pv.x[d][p] > hi[d]);
      return out;
    }));

    const double h = dx_ / per_axis_, shift = spec_.speed * t;
    long last = next_column_;
    while (origin_[0] + (double(last) + 0.5) * h - shift < spec_.inflow) ++last;
    if (last == next_column_) return;
    const double x_from = origin_[0] + double(next_column_) * h, x_to = origin_[0] + double(last) * h;
    next_column_ = last;
    const std::vector<Point> at_rest = columns(x_from, x_to);  // where they were at t = 0
    std::vector<Point> now = at_rest;
    for (Point& p : now) p[0] -= shift;
    const std::size_t first = sim.particle_count();
    const std::vector<std::size_t> order = add_table_particles(
        sim, materials_, spec_.material, at_rest, now, std::vector<Point>(now.size(), Point{-spec_.speed, 0, 0}), volume_);
    const ParticleView<T> pv = sim.particles();
    if (pv.x0[0])
      for (std::size_t k = 0; k < order.size(); ++k) pv.x0[0][first + k] = T(at_rest[order[k]][0]);
    injected_ += long(now.size());
  }

  // The columns injected so far and the counts, for checkpoints.
  void save_state(StateWriter& out) const { state_fields(out, *this); }
  void load_state(StateReader& in) { state_fields(in, *this); }

  long injected() const { return injected_; }
  long removed() const { return removed_; }
  const ConveyorSpec& spec() const { return spec_; }

 private:
  template <class Stream, class Self>
  static void state_fields(Stream& s, Self& c) {
    s.field(c.next_column_);
    s.field(c.injected_);
    s.field(c.removed_);
  }

  // The bed's lattice sites with x_from <= x < x_to at t = 0.
  std::vector<Point> columns(double x_from, double x_to) const {
    return fill_box(origin_, dx_, per_axis_, {x_from, spec_.ground, spec_.z_min},
                    {x_to, spec_.ground + spec_.depth, spec_.z_max});
  }

  ConveyorSpec spec_;
  SceneMaterials materials_;  // the bed's levels, where its table is varied
  Point origin_;
  double dx_;
  int per_axis_;
  Point domain_min_, domain_max_;
  double volume_;
  long next_column_ = 0;
  long injected_ = 0, removed_ = 0;
};

}  // namespace firn
