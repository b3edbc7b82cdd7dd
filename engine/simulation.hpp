// The engine's step loop and the small C++ API to build a simulation in code (used by tests,
// benchmarks and `firn verify`; scene files build on it).
//
//   Simulation<float, backend::OpenMP> sim(config);
//   int snow = sim.add_material({"snow", "neo_hookean", 400, ElasticModuli::from_E_nu(1.4e5, 0.2)});
//   sim.add_particles(snow, fill_sphere(...), {0, 0, -2}, volume_per_particle);
//   sim.advance_to(1.0);
//
// One step reads like the algorithm (DESIGN.md section 3):
//   bin -> F-bar volume averaging (nearly incompressible materials) -> constitutive update (return
//   mapping and stress, one launch per material) -> P2G ->
//   grid update (gravity, colliders, walls) -> G2P with the stability guard.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "engine/block_compaction.hpp"
#include "engine/collider_body.hpp"
#include "engine/contact_pool_solve.hpp"
#include "engine/elastic_moduli.hpp"
#include "engine/materials.hpp"
#include "engine/particle_binning.hpp"
#include "engine/particle_fields.hpp"
#include "engine/particle_fill.hpp"
#include "engine/particle_storage.hpp"
#include "engine/radix_order.hpp"
#include "engine/state_stream.hpp"
#include "engine/sparse_grid.hpp"
#include "engine/stability_guard.hpp"
#include "kernels/backend/openmp.hpp"
#include "kernels/backend/reduce_chunks.hpp"
#include "kernels/backend/schedule.hpp"
#include "kernels/backend/serial.hpp"
#include "kernels/binning_view.hpp"
#include "kernels/body_acceleration.hpp"
#include "kernels/boundary_conditions.hpp"
#include "kernels/colliders.hpp"
#include "kernels/combine.hpp"
#include "kernels/grid_update.hpp"
#include "kernels/guard_summary.hpp"
#include "kernels/hd.hpp"
#include "kernels/motion_sums.hpp"
#include "kernels/particle_regroup.hpp"
#include "kernels/particle_state.hpp"
#include "kernels/shape_functions.hpp"
#include "kernels/step/collider_sums.hpp"
#include "kernels/step/constitutive_update.hpp"
#include "kernels/step/elastic_energy.hpp"
#include "kernels/step/contact_normals.hpp"
#include "kernels/step/contact_pool_moments.hpp"
#include "kernels/step/contact_pool_sums.hpp"
#include "kernels/step/contact_update.hpp"
#include "kernels/step/g2p_gather.hpp"
#include "kernels/step/grid_update_slots.hpp"
#include "kernels/step/mirror_walls.hpp"
#include "kernels/step/load_work.hpp"
#include "kernels/step/p2g_scatter.hpp"
#include "kernels/step/penalty_contact.hpp"
#include "kernels/step/volume_average.hpp"
#include "kernels/transfer.hpp"

namespace firn {

struct SimulationConfig {
  Point domain_min = {0, 0, 0};
  Point domain_max = {1, 1, 1};
  double dx = 0.01;
  Point gravity = {0, -9.81, 0};
  double cfl = 0.4;        // dt = cfl dx / max_p(c_p + |v_p|)
  double dt_max = 1e-3;    // cap on the adaptive step
  double fixed_dt = 0;     // when > 0, every step uses it (benchmarks, convergence studies)
  double damping = 0;      // grid velocity damping rate (1/s), kernels/grid_update.hpp; 0: none
  Transfer transfer = Transfer::apic;
  double flip_alpha = 0.95;
  Shape shape = Shape::quadratic;
  // Faces -x, +x, -y, +y, -z, +z: by default separating frictionless walls 3 cells thick.
  std::array<Wall<double>, 6> walls = {{{WallType::separate, 3, 0}, {WallType::separate, 3, 0},
                                        {WallType::separate, 3, 0}, {WallType::separate, 3, 0},
                                        {WallType::separate, 3, 0}, {WallType::separate, 3, 0}}};
  // Grid nodes along axis d: the domain's length in cells, plus one.
  int nodes(int d) const { return int(std::lround((domain_max[d] - domain_min[d]) / dx)) + 1; }
};

struct Diagnostics {
  double kinetic_energy = 0;  // sum 1/2 m |v|^2 (J)
  double elastic_energy = 0;  // sum V0 W(F) (J)
  double momentum[3] = {0, 0, 0};
  double max_speed = 0;
  double min_J = 0;
};

// The energy budget of a run (issue 19): the work done on the material since the budget was
// enabled (kernels/grid_update.hpp, kernels/step/load_work.hpp), and the energy its plasticity took
// out of the elastic store (kernels/step/constitutive_update.hpp), in J. With the kinetic and
// elastic energy E(t) = K + W, the residual E(0) + gravity + colliders + loads - plastic - E(t) is
// what the discretisation dissipated: the transfers' numerical dissipation and what the walls and
// colliders take out of the motion they stop or rub, what a grid damping (SimulationConfig::damping)
// takes, and, in a conveyor scene, the energy of the particles it injects and removes.
struct EnergyBudget {
  double gravity = 0, colliders = 0, loads = 0;  // work on the material
  double plastic = 0;                            // V0 (W(F_trial) - W(F_returned)), summed
};

// The vertical force of one collider summed per grid column (x, z) and integrated over time since
// the last reset: the footprint's contact pressure is impulse / (time dx^2).
struct FootprintMap {
  int nx = 0, nz = 0;              // grid nodes along x and z; column (i, k) at origin + (i, k) dx
  double origin_x = 0, origin_z = 0, dx = 0;
  AlignedVector<double> impulse;   // [i * nz + k] (N s)
  double time = 0;                 // integration time (s)
  void reset() {
    std::fill(impulse.begin(), impulse.end(), 0.0);
    time = 0;
  }
};

template <class T, class Backend>
class Simulation {
 public:
  explicit Simulation(const SimulationConfig& config, Backend backend = Backend{})
      : config_(config), backend_(backend) {
    if (!(config.dx > 0)) throw std::invalid_argument("dx must be positive");
    GridGeometry<T> g{};
    for (int d = 0; d < 3; ++d) {
      if (!(config.domain_max[d] > config.domain_min[d])) throw std::invalid_argument("empty domain");
      g.origin[d] = T(config.domain_min[d]);
      g.nodes[d] = config.nodes(d);
    }
    g.dx = T(config.dx);
    g.inv_dx = T(1 / config.dx);
    check_mirror_walls(config, g.nodes);
    if (config.transfer == Transfer::apic) storage_.enable(Attribute::C);  // only APIC's P2G reads C
    const int channels = config.transfer == Transfer::flip ? GridChannels<Transfer::flip>::kCount
                                                           : GridChannels<Transfer::apic>::kCount;
    grid_.configure(g, channels);
    contact_.grid_b.configure(g, channels);
    contact_.normals.configure(g, kContactNormalChannels);
    pool_moments_.configure(g, kContactNormalChannels);
  }

  int add_material(const MaterialInfo& info) {
    Material m{info, make_material_model<T>(info), {0, 0}, info.wave_speed(), uses_volume_averaging(info)};
    if (m.volume_averaged && averaged_material_count() >= ParticleRanges::kMax)
      throw std::invalid_argument("at most " + std::to_string(ParticleRanges::kMax) +
                                  " nearly incompressible materials (F-bar volume averaging)");
    std::visit(
        [this](const auto& model) {
          using Model = std::decay_t<decltype(model)>;
          if (Model::kUsesAlpha) enable(Attribute::alpha);
          if (Model::kUsesJp) enable(Attribute::Jp);
        },
        m.model);
    materials_.push_back(m);
    return int(materials_.size()) - 1;
  }

  // Puts `material` in contact group `group` (0, the default, or 1). Bodies of different groups
  // move on their own grids and meet through frictional contact (kernels/step/contact_update.hpp)
  // with `friction`; with every particle in one group the step is the single-grid one.
  void set_contact_group(int material, int group, const Friction<double>& friction) {
    if (material < 0 || material >= int(materials_.size())) throw std::invalid_argument("unknown material index");
    if (group != 0 && group != 1) throw std::invalid_argument("contact group must be 0 or 1");
    if (materials_.size() > 64) throw std::invalid_argument("contact groups take at most 64 materials");
    contact_.group.resize(materials_.size(), 0);
    contact_.group[std::size_t(material)] = group;
    contact_.friction = friction;
  }

  // Adds particles of one material at rest in F = I, each of rest volume `volume`, all moving with
  // `velocity`.
  void add_particles(int material, const std::vector<Point>& positions, const Point& velocity, double volume) {
    add_particles(material, positions, std::vector<Point>(positions.size(), velocity), volume);
  }

  // As above, with a velocity per particle. Until the next step or prepare(), the new particles
  // hold the last positions.size() indices of particles().
  void add_particles(int material, const std::vector<Point>& positions, const std::vector<Point>& velocities,
                     double volume) {
    if (material < 0 || material >= int(materials_.size())) throw std::invalid_argument("unknown material index");
    const std::size_t n0 = storage_.size();
    if (prepared_)  // particles already grouped: restate their materials before staging more
      for (std::size_t m = 0; m < materials_.size(); ++m)
        staged_.push_back({int(m), materials_[m].range.begin, materials_[m].range.end - materials_[m].range.begin});
    storage_.resize(n0 + positions.size());
    ParticleView<T> pv = storage_.view();
    const T mass = T(materials_[material].info.density * volume);
    for (std::size_t i = 0; i < positions.size(); ++i) {
      const std::size_t p = n0 + i;
      for (int d = 0; d < 3; ++d) {
        pv.x[d][p] = T(positions[i][d]);
        pv.v[d][p] = T(velocities[i][d]);
        if (pv.x0[d]) pv.x0[d][p] = T(positions[i][d]);
      }
      for (int q = 0; q < 9; ++q) pv.F[q][p] = T(q % 4 == 0);
      if (pv.Jp) pv.Jp[p] = T(1);
      pv.mass[p] = mass;
      pv.vol0[p] = T(volume);
      pv.id[p] = next_id_++;
    }
    staged_.push_back({int(material), n0, positions.size()});
    prepared_ = false;
  }

  // Removes the particles p for which remove(view, p) is true (a kernel-style predicate, evaluated
  // in parallel) and returns how many. The others keep their material and, but for a few, their
  // order: each material's holes are filled with its own kept particles from the end of its range,
  // and a material after one that lost particles moves its last few into the gap they left. So a
  // removal moves no more particles than it removes, those of the materials after them aside (a
  // conveyor removes particles every other step; a gather of every particle each time was an eighth
  // of a long tire run's step, issue 15), and the step's reorder puts the moved ones back in block
  // order when that pays (ParticleBinning::needs_reorder).
  template <class Predicate>
  std::size_t remove_particles(Predicate remove) {
    prepare();
    const ParticleView<T> pv = storage_.view();
    std::size_t kept = 0, doomed = 0;  // the particles kept in the materials before m, and removed
    for (auto& m : materials_) {
      const std::size_t first = m.range.begin, n = m.range.end - first;
      if (n == 0) {  // no launches for a material without particles
        m.range = {kept, kept};
        continue;
      }
      const std::size_t removed = backend_.parallel_reduce(
          "particles.count_removed", n, std::size_t(0),
          [=] FIRN_HD_LAMBDA(std::size_t i, std::size_t& acc) { acc += remove(pv, first + i) ? 1 : 0; }, Sum{});
      const std::size_t end = m.range.end - removed;  // the material's kept particles: [first, end)
      if (removed > 0) {
        const auto begins = refill_.count(n, RefillClass<T, Predicate>{remove, pv, first, end}, backend_);
        const std::size_t holes = begins[1];
        if (begins[2] != 2 * holes)  // as many sources as holes, unless the predicate changed its mind
          throw std::logic_error("remove_particles: the predicate gave different answers for the same particles");
        if (holes > 0) {  // none where only the tail's particles go
          if (moves_.size() < 2 * holes) moves_.resize(2 * holes);
          refill_.write(RefillList{moves_.data(), first}, backend_);
          storage_.move(moves_.data(), holes, backend_);
        }
      }
      // Into the gap [kept, first) the earlier materials left: the range's last particles, at most
      // as many as the gap holds, so that no source is a destination.
      const std::size_t shift = std::min(first - kept, end - first);
      if (shift > 0) {
        if (moves_.size() < 2 * shift) moves_.resize(2 * shift);
        backend_.parallel_for("particles.shift", shift, RunMoves{moves_.data(), kept, end - shift, shift});
        storage_.move(moves_.data(), shift, backend_);
      }
      m.range = {kept, kept + (end - first)};
      kept += end - first;
      doomed += removed;
    }
    storage_.resize(kept);
    return doomed;
  }

  // Adds a rigid collider (at most kMaxColliders) and returns its index.
  int add_collider(const ColliderBody& c) {
    if (int(colliders_.size()) >= kMaxColliders)
      throw std::invalid_argument("at most " + std::to_string(kMaxColliders) + " colliders");
    if (c.motion == ColliderBody::Motion::loaded_axle && !(c.mass > 0))
      throw std::invalid_argument("a loaded axle needs a positive mass");
    if (c.free_spin && !(c.inertia > 0)) throw std::invalid_argument("a free spin needs a positive moment of inertia");
    if (c.collider.contact == ColliderContact::pooled && pooled_collider() >= 0)
      throw std::invalid_argument("at most one collider with contact = pooled");
    if (c.collider.contact == ColliderContact::pooled && c.collider.boundary != WallType::separate)
      throw std::invalid_argument("a pooled collider needs boundary separate");
    if (c.collider.contact == ColliderContact::penalty && c.collider.boundary != WallType::separate)
      throw std::invalid_argument("a penalty collider needs boundary separate: it only pushes");
    if (c.collider.contact == ColliderContact::penalty && !(c.penalty_stiffness > 0))
      throw std::invalid_argument("a penalty collider needs a positive penalty_stiffness");
    colliders_.push_back(c);
    penalty_sums_.emplace_back();
    return int(colliders_.size()) - 1;
  }

  // Starts summing the vertical force of collider `c` per grid column (x, z) into footprint().
  void enable_footprint(int c) {
    const GridGeometry<T> g = grid_.geometry();
    footprint_collider_ = c;
    footprint_.nx = g.nodes[0];
    footprint_.nz = g.nodes[2];
    footprint_.origin_x = double(g.origin[0]);
    footprint_.origin_z = double(g.origin[2]);
    footprint_.dx = config_.dx;
    footprint_.impulse.assign(std::size_t(footprint_.nx) * std::size_t(footprint_.nz), 0.0);
    footprint_.time = 0;
  }

  // A total force spread over the particles inside [lo, hi] when the run starts, in proportion to
  // their mass (every such particle gets the acceleration force / total mass), ramped linearly
  // from zero over ramp_time (0: applied at once). A particle carries the first load that holds it.
  void add_load(const Point& lo, const Point& hi, const Point& force, double ramp_time) {
    loads_.push_back({lo, hi, force, ramp_time, {0, 0, 0}, -1});
    loads_assigned_ = false;
  }

  // A follower pressure (kernels/body_acceleration.hpp), for a tire's inflation: particle first + k
  // carries the rest area vector areas[k] (N dA in m^2, N pointing from the pressurised side into
  // the body); call it after adding those particles and before the first step (or prepare()). The
  // pressure (Pa) acts on every such area, ramped linearly from zero over ramp_time (0: at once).
  void add_pressure_surface(std::size_t first, const std::vector<Point>& areas) {
    if (prepared_) throw std::invalid_argument("pressure surfaces are added before the first step");
    if (first + areas.size() > storage_.size()) throw std::invalid_argument("pressure surface past the particles");
    enable(Attribute::area0);
    enable(Attribute::body_accel);
    ParticleView<T> pv = storage_.view();
    for (std::size_t k = 0; k < areas.size(); ++k)
      for (int d = 0; d < 3; ++d) pv.area0[d][first + k] = T(areas[k][d]);
  }
  void set_pressure(double pressure, double ramp_time) { pressure_ = {pressure, ramp_time}; }

  // Allocates an on_demand attribute with its initial value: x0 the current positions, Jp one,
  // anything else zero.
  void enable(Attribute a) {
    if (storage_.has(a)) return;
    storage_.enable(a);
    ParticleView<T> pv = storage_.view();
    if (a == Attribute::x0)
      for (int d = 0; d < 3; ++d)
        for (std::size_t p = 0; p < pv.n; ++p) pv.x0[d][p] = pv.x[d][p];
    if (a == Attribute::Jp)
      for (std::size_t p = 0; p < pv.n; ++p) pv.Jp[p] = T(1);
  }

  bool has(Attribute a) const { return storage_.has(a); }

  // Groups particles by material (stable) and measures the initial speed for the time step. Called by
  // the first step; call it yourself to read particles in their final layout before stepping.
  void prepare() {
    if (prepared_) return;
    // Group the particles by material, each material's runs in the order they were staged; the
    // columns move (on the backend) only where that is not the order they have.
    runs_.clear();
    std::size_t next = 0;
    bool in_place = true;
    for (std::size_t m = 0; m < materials_.size(); ++m) {
      materials_[m].range.begin = next;
      for (const StagedRun& r : staged_)
        if (r.material == int(m) && r.count) {
          runs_.push_back({next, r.begin, r.count});
          in_place = in_place && r.begin == next;
          next += r.count;
        }
      materials_[m].range.end = next;
    }
    staged_.clear();
    if (!in_place) {
      if (regroup_.size() < next) regroup_.resize(next);
      backend_.parallel_for("particles.group", next, RunOrder{runs_.data(), runs_.size(), regroup_.data()});
      storage_.gather(regroup_.data(), next, backend_);
    }
    const ParticleView<T> pv = storage_.view();
    max_speed_ = backend_.parallel_reduce(
        "particles.max_speed", pv.n, T(0),
        [=] FIRN_HD_LAMBDA(std::size_t p, T& acc) {
          acc = std::max(acc, std::sqrt(pv.v[0][p] * pv.v[0][p] + pv.v[1][p] * pv.v[1][p] + pv.v[2][p] * pv.v[2][p]));
        },
        Max{});
    const T lightest = backend_.parallel_reduce(
        "particles.min_mass", pv.n, std::numeric_limits<T>::max(),
        [=] FIRN_HD_LAMBDA(std::size_t p, T& acc) { acc = std::min(acc, pv.mass[p]); }, Min{});
    min_node_mass_ = T(kEmptyNodeMassFraction * (pv.n ? double(lightest) : std::numeric_limits<double>::max()));
    if (pooled_collider() >= 0 && contact_active())
      throw std::invalid_argument("a collider with contact = pooled cannot be used with two contact groups");
    if (pooled_collider() >= 0 && mirror_planes<T>(config_.walls.data(), grid_.geometry().nodes).any())
      throw std::invalid_argument("a collider with contact = pooled cannot be used with mirror walls");
    prepared_ = true;
  }

  // The next adaptive (or fixed) time step.
  double next_dt() const {
    if (config_.fixed_dt > 0) return config_.fixed_dt;
    const double dt = config_.cfl * config_.dx / (wave_speed() + double(max_speed_));
    return std::min(dt, config_.dt_max);
  }

  // The fastest P-wave speed of the materials with particles, as of the last stress pass (`now`) or
  // at rest.
  double wave_speed(bool now = true) const {
    double c = 0;
    for (const auto& m : materials_)
      if (m.range.end > m.range.begin) c = std::max(c, now ? m.wave_speed : m.info.wave_speed());
    return c;
  }

  void step() { step(next_dt()); }

  // One step of dt (defined below the class, as is diagnostics()).
  void step(double dt);

  // Steps until `time`, shortening the last step to land on it exactly.
  void advance_to(double time) {
    while (time_ < time * (1 - 1e-12)) step(std::min(next_dt(), time - time_));
  }

  // Kinetic and elastic energy, momentum, the largest speed and the smallest J of the particles.
  Diagnostics diagnostics();

  // Physical indices of the particles in increasing id (ids are unique), into `order`, with the
  // sort's buffers (engine/radix_order.hpp); the form that returns them allocates all three.
  void id_order(std::vector<std::uint32_t>& order, RadixBuffers& buffers) {
    const ParticleView<T> pv = storage_.view();
    radix_order(pv.id, pv.n, order, buffers);
  }
  std::vector<std::uint32_t> id_order() {
    std::vector<std::uint32_t> order;
    RadixBuffers buffers;
    id_order(order, buffers);
    return order;
  }

  // FNV-1a over every particle's position and velocity bits, in particle id order: equal states
  // give equal hashes whatever the memory layout.
  std::uint64_t state_hash() {
    const ParticleView<T> pv = storage_.view();
    const std::vector<std::uint32_t> by_id = id_order();
    std::uint64_t h = 1469598103934665603ull;
    auto mix = [&h](T value) {
      unsigned char bytes[sizeof(T)];
      std::memcpy(bytes, &value, sizeof(T));
      for (unsigned char b : bytes) h = (h ^ b) * 1099511628211ull;
    };
    for (std::uint32_t p : by_id)
      for (int d = 0; d < 3; ++d) {
        mix(pv.x[d][p]);
        mix(pv.v[d][p]);
      }
    return h;
  }

  // The state a step depends on, for checkpoints (engine/scene/checkpoint.hpp): time and step
  // count, the particles in their memory order (sums over particles follow it, so it is part of
  // the state for bitwise equality), the materials' ranges and wave speeds, the colliders' poses,
  // velocities and reactions, the loads' ramps, the footprint, the energy budget and the breaks
  // that decide the next reorder of the particles. What the scene defines (material parameters,
  // collider shapes, load regions) is not saved: load_state() restores into a simulation built
  // from the same scene, and refuses one that differs in precision, materials, colliders, loads or
  // footprint.
  void save_state(StateWriter& out) {
    prepare();
    out.value(std::uint32_t(sizeof(T)));
    out.value(std::uint64_t(materials_.size()));
    out.value(std::uint64_t(colliders_.size()));
    out.value(std::uint64_t(loads_.size()));
    out.value(std::uint64_t(footprint_.impulse.size()));
    state_fields(out, *this);
    out.value(std::uint8_t(loads_assigned_));
    for (const ColliderBody& c : colliders_) c.save_motion(out);
    storage_.save(out);
  }

  void load_state(StateReader& in) {
    prepare();  // the scene's own particles grouped, so that they are replaced whole
    using R = StateReader;
    R::expect(in.value<std::uint32_t>() == sizeof(T), "checkpoint's precision differs from the scene's");
    R::expect(in.value<std::uint64_t>() == materials_.size(), "checkpoint's materials differ from the scene's");
    R::expect(in.value<std::uint64_t>() == colliders_.size(), "checkpoint's colliders differ from the scene's");
    R::expect(in.value<std::uint64_t>() == loads_.size(), "checkpoint's loads differ from the scene's");
    R::expect(in.value<std::uint64_t>() == footprint_.impulse.size(), "checkpoint's footprint differs from the scene's");
    state_fields(in, *this);
    loads_assigned_ = in.value<std::uint8_t>() != 0;
    for (ColliderBody& c : colliders_) c.load_motion(in);
    storage_.load(in);
    std::size_t end = 0;
    for (const Material& m : materials_) {
      R::expect(m.range.begin == end && m.range.end >= m.range.begin, "checkpoint's material ranges are inconsistent");
      end = m.range.end;
    }
    R::expect(end == storage_.size(), "checkpoint's material ranges do not cover its particles");
  }

  ParticleView<T> particles() { return storage_.view(); }
  std::size_t collider_count() const { return colliders_.size(); }
  const ColliderBody& collider(int c) const { return colliders_[std::size_t(c)]; }
  ColliderBody& collider(int c) { return colliders_[std::size_t(c)]; }
  const FootprintMap& footprint() const { return footprint_; }
  FootprintMap& footprint() { return footprint_; }
  // Starts the energy budget (it costs an extra elastic energy per plastic return mapping and a few
  // products per grid node); energy_budget() is zero until then.
  void enable_energy_budget() { budget_enabled_ = true; }
  const EnergyBudget& energy_budget() const { return budget_; }
  std::size_t particle_count() const { return storage_.size(); }
  std::size_t bytes_per_particle() const { return storage_.bytes_per_particle(); }
  double time() const { return time_; }
  long steps() const { return steps_; }
  double last_dt() const { return last_dt_; }
  const SimulationConfig& config() const { return config_; }
  const Backend& backend() const { return backend_; }
  Backend& backend() { return backend_; }
  const SparseGrid<T>& grid() const { return grid_; }
  const MaterialInfo& material(int m) const { return materials_[m].info; }
  std::size_t material_count() const { return materials_.size(); }
  // det of the whole deformation gradient F_E F_P of the particle at physical index p.
  static T total_J(const ParticleView<T>& pv, std::size_t p) { return particle_total_J(pv, p); }
  // The physical indices [begin, end) of material m's particles (valid after prepare()).
  ParticleRange material_range(int m) const { return materials_[std::size_t(m)].range; }
  // Material index of the particle at physical index p (valid after prepare()).
  int material_of(std::size_t p) const {
    for (std::size_t m = 0; m < materials_.size(); ++m)
      if (p < materials_[m].range.end) return int(m);
    return -1;
  }

 private:
  struct Material {
    MaterialInfo info;
    MaterialModel<T> model;
    ParticleRange range;
    double wave_speed;  // max over its particles of sqrt(p_wave_modulus / density), last stress pass
    bool volume_averaged;  // F-bar (kernels/step/volume_average.hpp) before its stress
  };

  int averaged_material_count() const {
    int n = 0;
    for (const Material& m : materials_) n += m.volume_averaged;
    return n;
  }

  // The physical index ranges of the materials with particles that `holds` picks (valid after
  // prepare()); throws past ParticleRanges::kMax.
  template <class Pick>
  ParticleRanges ranges_where(Pick holds) const {
    ParticleRanges r;
    for (std::size_t m = 0; m < materials_.size(); ++m)
      if (holds(m) && materials_[m].range.end > materials_[m].range.begin) {
        if (r.count == ParticleRanges::kMax) throw std::invalid_argument("too many materials in one particle range set");
        r.begin[r.count] = materials_[m].range.begin;
        r.end[r.count] = materials_[m].range.end;
        ++r.count;
      }
    return r;
  }

  // The collider with contact = pooled, or -1.
  int pooled_collider() const {
    for (std::size_t c = 0; c < colliders_.size(); ++c)
      if (colliders_[c].collider.contact == ColliderContact::pooled) return int(c);
    return -1;
  }

  int contact_group(std::size_t m) const { return m < contact_.group.size() ? contact_.group[m] : 0; }

  // Whether both contact groups have particles (valid after prepare()).
  bool contact_active() const {
    bool any[2] = {false, false};
    for (std::size_t m = 0; m < materials_.size(); ++m)
      if (materials_[m].range.end > materials_[m].range.begin) any[contact_group(m)] = true;
    return any[0] && any[1];
  }

  // The binning restricted to contact group `group`'s materials (bucket indices count only the
  // materials with particles, as the binning does).
  BinningView group_bins(int group) const {
    BinningView v = binning_.view();
    v.material_mask = 0;
    std::size_t bucket = 0;
    for (std::size_t m = 0; m < materials_.size(); ++m) {
      if (materials_[m].range.end == materials_[m].range.begin) continue;
      if (contact_group(m) == group) v.material_mask |= std::uint64_t(1) << bucket;
      ++bucket;
    }
    return v;
  }

  // F-bar by volume averaging (kernels/step/volume_average.hpp) for the averaged materials, on the
  // grid activated by bin(), which it leaves cleared for P2G: each contact group's among themselves
  // (bodies in contact do not share their volume change). No launch for a group without them.
  template <class ShapeT>
  void average_volume() {
    for (int group = 0; group < 2; ++group) {
      const ParticleRanges averaged =
          ranges_where([&](std::size_t m) { return materials_[m].volume_averaged && contact_group(m) == group; });
      if (averaged.count == 0) continue;
      const ParticleView<T> pv = storage_.view();
      const SparseGridView<T> gv = grid_.view();
      const BinningView bins = binning_.view();
      const GridGeometry<T> g = grid_.geometry();
      backend_.scatter_blocks("volume_average.p2g", binning_.colouring(),
                              VolumeScatter<T, ShapeT>{pv, gv, bins, g, averaged});
      const AlignedVector<std::uint32_t>& blocks = binning_.particle_blocks();
      backend_.gather_blocks("volume_average.g2p", blocks.data(), blocks.size(),
                             VolumeGather<T, ShapeT>{pv, gv, bins, g, averaged}, Sum{});
      grid_.clear(backend_);
    }
  }

  // The scalar state of save_state and load_state, once for both directions (the counts of
  // materials, loads and footprint columns are checked before).
  template <class Stream, class Sim>
  static void state_fields(Stream& s, Sim& sim) {
    s.field(sim.time_);
    s.field(sim.last_dt_);
    s.field(sim.steps_);
    s.field(sim.next_id_);
    s.field(sim.max_speed_);
    s.field(sim.min_node_mass_);
    for (auto& m : sim.materials_) {
      s.field(m.range);
      s.field(m.wave_speed);
    }
    for (auto& l : sim.loads_) {
      s.field(l.accel);
      s.field(l.factor);
    }
    for (auto& f : sim.footprint_.impulse) s.field(f);
    s.field(sim.footprint_.time);
    s.field(sim.budget_);
    s.field(sim.binning_.walk_breaks());
  }

  std::vector<ParticleRange> ranges() const {
    std::vector<ParticleRange> r;
    for (const auto& m : materials_) r.push_back(m.range);
    return r;
  }

  // One step: bin -> F-bar volume averaging (nearly incompressible materials only) -> constitutive
  // update -> the penalty colliders' pushes (only where a collider has contact = penalty) -> P2G ->
  // grid update -> G2P with the stability guard. With two contact groups, each
  // group has its own F-bar, P2G, grid update and G2P, and between the grid updates and G2P the
  // contact update joins them (kernels/step/contact_update.hpp).
  template <class ShapeT, Transfer kTransfer>
  void step_impl(T dt) {
    bin<ShapeT>(dt);
    average_volume<ShapeT>();
    update_stress(dt);
    const GridGeometry<T> g = grid_.geometry();
    const ParticleView<T> pv = storage_.view();
    const bool load_work = budget_enabled_ && storage_.has(Attribute::body_accel);
    if (load_work)  // half of it with the velocities at the step's start, half at its end
      budget_.loads += backend_.parallel_reduce("energy_budget.loads", pv.n, 0.0, LoadWork<T>{pv, dt}, Sum{});
    push_penalty_colliders(dt);
    const SparseGridView<T> gv = grid_.view();
    const bool contact = contact_active();
    const BinningView bins = contact ? group_bins(0) : binning_.view();
    backend_.scatter_blocks("p2g", binning_.colouring(), P2GScatter<T, ShapeT, kTransfer>{pv, gv, bins, g, dt});
    const BinningView bins_b = contact ? group_bins(1) : bins;
    if (contact) {
      backend_.scatter_blocks("p2g", binning_.colouring(),
                              P2GScatter<T, ShapeT, kTransfer>{pv, contact_.grid_b.view(), bins_b, g, dt});
      const ParticleRanges group_b = ranges_where([&](std::size_t m) { return contact_group(m) == 1; });
      backend_.scatter_blocks("contact.normals", binning_.colouring(),
                              ContactNormalScatter<T, ShapeT>{pv, contact_.normals.view(), binning_.view(), g, group_b});
    }
    const MirrorPlanes<T> mirror = mirror_planes<T>(config_.walls.data(), g.nodes);
    if (mirror.any()) fold_mirror_images<kTransfer>(mirror, dt, contact);
    pose_colliders(dt, contact);
    const int pooled = pooled_collider();
    if (pooled >= 0) {  // with one group, the normals' first channels are the mass moments pool_node reads
      backend_.scatter_blocks("contact.pool_moments", binning_.colouring(),
                              ContactPoolMomentsScatter<T, ShapeT>{{pv, pool_moments_.view(), bins, g, ParticleRanges{}},
                                                                   &grid_params_[0], pooled});
      solve_contact_pool<kTransfer>(pooled);
    }
    backend_.parallel_for("grid_update", grid_.active_count(), GridUpdateSlots<T, kTransfer>{grid_.slots(), &grid_params_[0]},
                          backend::Schedule::blocks);
    if (contact) {
      backend_.parallel_for("grid_update", grid_.active_count(),
                            GridUpdateSlots<T, kTransfer>{contact_.grid_b.slots(), &grid_params_[1]},
                            backend::Schedule::blocks);
      const Friction<T> friction{contact_.friction.law, T(contact_.friction.mu)};
      backend_.parallel_for("contact", grid_.active_count(),
                            ContactUpdateSlots<T, kTransfer>{grid_.slots(), contact_.grid_b.slots(),
                                                             contact_.normals.slots(), min_node_mass_,
                                                             T(kContactVolumeFraction) * g.dx * g.dx * g.dx, friction},
                            backend::Schedule::blocks);
    }
    if (mirror.any()) set_mirror_ghosts<kTransfer>(mirror, contact);
    collect_reactions(double(dt), contact);
    if (budget_enabled_) collect_work(contact);
    const AlignedVector<std::uint32_t>& blocks = binning_.particle_blocks();
    GuardSummary<T> guard =
        backend_.gather_blocks("g2p", blocks.data(), blocks.size(),
                               G2PGather<T, ShapeT, kTransfer>{pv, gv, bins, g, dt, T(config_.flip_alpha)}, MergeGuard{});
    if (contact)
      guard.merge(backend_.gather_blocks(
          "g2p", blocks.data(), blocks.size(),
          G2PGather<T, ShapeT, kTransfer>{pv, contact_.grid_b.view(), bins_b, g, dt, T(config_.flip_alpha)}, MergeGuard{}));
    if (guard.reason != GuardReason::none) fail(guard, dt);
    if (load_work) budget_.loads += backend_.parallel_reduce("energy_budget.loads", pv.n, 0.0, LoadWork<T>{pv, dt}, Sum{});
    max_speed_ = guard.max_speed;
  }

  // Mirror walls (kernels/step/mirror_walls.hpp): the ghost rows' P2G sums folded onto their inner
  // images before the grid update, on each contact group's grid.
  template <Transfer kTransfer>
  void fold_mirror_images(const MirrorPlanes<T>& mirror, T dt, bool contact) {
    const T g[3] = {T(config_.gravity[0]), T(config_.gravity[1]), T(config_.gravity[2])};
    backend_.parallel_for("mirror.fold", grid_.active_count(),
                          MirrorFold<T, kTransfer>{grid_.slots(), grid_.view(), mirror, dt, {g[0], g[1], g[2]}},
                          backend::Schedule::blocks);
    if (contact)
      backend_.parallel_for("mirror.fold", grid_.active_count(),
                            MirrorFold<T, kTransfer>{contact_.grid_b.slots(), contact_.grid_b.view(), mirror, dt,
                                                     {g[0], g[1], g[2]}},
                            backend::Schedule::blocks);
  }

  // ... and the ghost nodes given their images' velocities after it.
  template <Transfer kTransfer>
  void set_mirror_ghosts(const MirrorPlanes<T>& mirror, bool contact) {
    backend_.parallel_for("mirror.ghosts", grid_.active_count(),
                          MirrorGhosts<T, kTransfer>{grid_.slots(), grid_.view(), mirror}, backend::Schedule::blocks);
    if (contact)
      backend_.parallel_for("mirror.ghosts", grid_.active_count(),
                            MirrorGhosts<T, kTransfer>{contact_.grid_b.slots(), contact_.grid_b.view(), mirror},
                            backend::Schedule::blocks);
  }

  // Throws for a mirror wall that cannot be one (kernels/step/mirror_walls.hpp, mirror_wall_error).
  static void check_mirror_walls(const SimulationConfig& config, const int nodes[3]) {
    for (int f = 0; f < 6; ++f) {
      const Wall<double>& w = config.walls[f];
      const std::string why = w.mirror ? mirror_wall_error(w.type, w.width, w.friction, nodes[f / 2]) : "";
      if (!why.empty())
        throw std::invalid_argument("the mirror wall on face " + std::string(f % 2 ? "+" : "-") + "xyz"[f / 2] + ": " +
                                    why);
    }
  }

  // Bins particles by block, reorders the arrays when the walk has become scattered and activates
  // the grid blocks the particles touch.
  template <class ShapeT>
  void bin(T dt) {
    const std::size_t outside = binning_.compute_keys<ShapeT>(storage_.view(), ranges(), grid_.geometry(), grid_.blocks(), backend_);
    if (outside != ParticleBinning::kNone) {
      GuardSummary<T> s;
      s.offender = outside;
      s.reason = GuardReason::left_grid;
      fail(s, dt);
    }
    binning_.sort(grid_.blocks(), backend_);
    if (binning_.needs_reorder(backend_)) {
      // Not tau: update_stress writes every particle's before P2G reads it (a sixth of the bytes
      // a reorder moves with APIC and J2 plasticity).
      storage_.gather(binning_.order(), storage_.size(), backend_, /*stress=*/false);
      binning_.reordered(backend_);
    }
    grid_.activate(binning_.occupied_blocks(), backend_);
    if (contact_active()) {  // the same blocks in the same slots as grid_
      contact_.grid_b.activate(binning_.occupied_blocks(), backend_);
      contact_.normals.activate(binning_.occupied_blocks(), backend_);
    }
    if (pooled_collider() >= 0) pool_moments_.activate(binning_.occupied_blocks(), backend_);
  }

  // The constitutive update, one launch per material range (kernels/step/constitutive_update.hpp);
  // a non-finite stress stops the run, and the largest P-wave modulus sets the wave speed.
  void update_stress(T dt) {
    const ParticleView<T> pv = storage_.view();
    std::size_t bad_stress = ParticleBinning::kNone;
    for (auto& m : materials_) {
      if (m.range.end == m.range.begin) continue;  // no launch for a material without particles
      std::visit(
          [&](const auto& model) {
            using Model = std::decay_t<decltype(model)>;
            const std::size_t n = m.range.end - m.range.begin;
            const ConstitutiveUpdate<T, Model> one{pv, model, m.range.begin, budget_enabled_};
            ConstitutiveSummary r;
            if constexpr (HasLanes<Model>::value) {  // batches of two of the backend's vectors
              using Batched = ConstitutiveUpdateLanes<T, Model, batch_width<T>(Backend::kVectorBytes)>;
              // Chunks of kReduceGrain particles, not batches: a material of a few chunks of
              // batches would leave threads idle.
              r = backend_.parallel_reduce(constitutive_launch_name<Model>(), Batched::batches(n),
                                           ConstitutiveSummary{}, Batched{one, n}, MergeConstitutive{},
                                           Batched::batches(backend::kReduceGrain));
            } else {
              r = backend_.parallel_reduce(constitutive_launch_name<Model>(), n, ConstitutiveSummary{}, one,
                                           MergeConstitutive{});
            }
            bad_stress = std::min(bad_stress, r.first_bad);
            budget_.plastic += r.plastic_work;
            m.wave_speed = std::sqrt(r.max_modulus / m.info.density);
          },
          m.model);
    }
    if (bad_stress != ParticleBinning::kNone) {
      GuardSummary<T> s;
      s.offender = bad_stress;
      s.reason = determinant(particle_F(pv, bad_stress)) <= T(0) ? GuardReason::inverted : GuardReason::not_finite;
      fail(s, dt);
    }
  }

  // The grid update's parameters, with the colliders posed at the end of the step; their reactions
  // are summed per block, then over blocks by a reduction on the backend (the same sums for any
  // thread count).
  void pose_colliders(T dt, bool contact) {
    const GridGeometry<T> g = grid_.geometry();
    GridUpdateParams<T>& up = grid_params_[0];
    up.dt = dt;
    up.dx = g.dx;
    up.min_mass = min_node_mass_;
    up.damping_factor = T(1 / (1 + config_.damping * double(dt)));
    up.collider_count = int(colliders_.size());
    for (std::size_t c = 0; c < colliders_.size(); ++c) {
      colliders_[c].advance(double(dt));
      up.colliders[c] = collider_cast<T>(colliders_[c].collider);
    }
    for (int d = 0; d < 3; ++d) {
      up.gravity[d] = T(config_.gravity[d]);
      up.nodes[d] = g.nodes[d];
      up.origin[d] = g.origin[d];
    }
    for (int f = 0; f < 6; ++f)
      up.walls[f] = Wall<T>{config_.walls[f].type, config_.walls[f].width, T(config_.walls[f].friction),
                            config_.walls[f].mirror};
    const std::size_t slots = grid_.active_count();
    // The grid update writes every entry of its per-block sums, so they are sized, not filled.
    reactions_.resize(slots * colliders_.size() * kReactionComponents);
    up.reactions = reactions_.data();
    up.work = nullptr;
    if (budget_enabled_) {
      work_.resize(slots * kWorkKinds);
      up.work = work_.data();
    }
    up.moments = pool_moments_.slots();
    for (int c = 0; c < kMaxColliders; ++c) up.pool_lambda[c] = up.pool_keep[c] = T(0);
    up.footprint_collider = footprint_collider_;
    up.footprint = nullptr;
    if (footprint_collider_ >= 0) {
      footprint_blocks_.resize(slots * kBlockSize * kBlockSize);
      up.footprint = footprint_blocks_.data();
    }
    if (!contact) return;
    // Group B's grid update: the same colliders and walls, its own per-block sums.
    GridUpdateParams<T>& b = grid_params_[1];
    b = up;
    contact_.reactions_b.resize(reactions_.size());
    b.reactions = contact_.reactions_b.data();
    if (up.work) {
      contact_.work_b.resize(work_.size());
      b.work = contact_.work_b.data();
    }
    if (up.footprint) {
      contact_.footprint_b.resize(footprint_blocks_.size());
      b.footprint = contact_.footprint_b.data();
    }
  }

  // The pooled collider's lambda and its surface row's friction share (engine/contact_pool_solve.hpp),
  // each evaluation of S(lambda) a backend reduction, the same for any thread count.
  template <Transfer kTransfer>
  void solve_contact_pool(int c) {
    GridUpdateParams<T>& up = grid_params_[0];
    const Friction<T>& friction = up.colliders[c].friction;
    const PoolSolution r = solve_pool(
        [&](double lambda) {
          return backend_.parallel_reduce("contact.pool", grid_.active_count(), DoubleSums<kPoolSums>{},
                                          ContactPoolSums<T, kTransfer>{grid_.slots(), &up, c, T(lambda)}, Sum{});
        },
        [&](double slip) { return double(friction.coefficient(T(slip))); });
    up.pool_lambda[c] = T(r.lambda);
    up.pool_keep[c] = T(r.keep);
  }

  // The penalty colliders' kicks (kernels/step/penalty_contact.hpp), posed at the step's start, with
  // omega = penalty_stiffness c / dx, c the materials' fastest P-wave speed at rest (fixed, so the
  // spring does not follow the state of the particles that set the step's wave speed); their
  // reactions wait in penalty_sums_ for collect_reactions.
  void push_penalty_colliders(T dt) {
    const ParticleView<T> pv = storage_.view();
    for (std::size_t c = 0; c < colliders_.size(); ++c) {
      penalty_sums_[c] = {};
      const ColliderBody& body = colliders_[c];
      if (body.collider.contact != ColliderContact::penalty) continue;
      const double omega = body.penalty_stiffness * wave_speed(/*now=*/false) / config_.dx;
      if (omega * double(dt) > kPenaltyStableOmegaDt)
        throw std::invalid_argument("a penalty collider's spring is unstable at this time step (omega dt = " +
                                    std::to_string(omega * double(dt)) + "): lower penalty_stiffness, cfl or fixed_dt");
      PenaltyContact<T> push{pv, collider_cast<T>(body.collider), {}, {}, T(omega * omega), dt};
      push.collider.bounds(push.lo, push.hi);
      for (int d = 0; d < 3; ++d) {  // a particle's radius is at most half a cell (one per cell)
        push.lo[d] -= T(config_.dx);
        push.hi[d] += T(config_.dx);
      }
      penalty_sums_[c] = backend_.parallel_reduce("contact.penalty", pv.n, DoubleSums<kPenaltySums>{}, push, Sum{});
      if (budget_enabled_) budget_.colliders += penalty_sums_[c].v[kPenaltyWork];
    }
  }

  // Sums the per-block collider reactions and footprint columns of the last grid update (both
  // contact groups' with `contact`) on the backend (kernels/step/collider_sums.hpp).
  void collect_reactions(double dt, bool contact) {
    const std::size_t count = colliders_.size(), slots = grid_.active_count();
    const T* b = contact ? contact_.reactions_b.data() : nullptr;
    for (std::size_t c = 0; c < count; ++c) {
      DoubleSums<kReactionComponents> f = backend_.parallel_reduce(
          "reactions", slots, DoubleSums<kReactionComponents>{},
          SlotSums<T, kReactionComponents>{reactions_.data(), b, count * kReactionComponents, c * kReactionComponents}, Sum{});
      if (colliders_[c].collider.contact == ColliderContact::penalty)
        for (int i = 0; i < kReactionComponents; ++i) f.v[i] += penalty_sums_[c].v[kPenaltyForce + i];
      colliders_[c].add_reaction(f.v, f.v + 3, dt);
    }
    if (footprint_collider_ < 0) return;
    const BlockBox box = grid_.box();
    backend_.parallel_for("footprint", std::size_t(box.count[0]) * std::size_t(box.count[2]),
                          FootprintColumns<T>{footprint_blocks_.data(), contact ? contact_.footprint_b.data() : nullptr,
                                              grid_.block_map(), box, dt, footprint_.impulse.data(), footprint_.nx,
                                              footprint_.nz},
                          backend::Schedule::blocks);
    footprint_.time += dt;
  }

  // Adds the per-block work of the last grid update to the budget.
  void collect_work(bool contact) {
    const DoubleSums<kWorkKinds> w =
        backend_.parallel_reduce("work", grid_.active_count(), DoubleSums<kWorkKinds>{},
                                 SlotSums<T, kWorkKinds>{work_.data(), contact ? contact_.work_b.data() : nullptr, kWorkKinds, 0}, Sum{});
    budget_.gravity += w.v[kGravityWork];
    budget_.colliders += w.v[kColliderWork];
  }

  struct Load {
    Point lo, hi, force;
    double ramp_time;
    Point accel;          // force / mass of the particles it holds
    double factor;        // ramp factor last written to body_accel (-1: never)
  };

  // Marks each particle with the first load whose region holds it and sets the loads' accelerations.
  void assign_loads() {
    loads_assigned_ = true;
    if (loads_.empty()) return;
    enable(Attribute::load);
    enable(Attribute::body_accel);
    ParticleView<T> pv = storage_.view();
    std::vector<double> mass(loads_.size(), 0.0);
    for (std::size_t p = 0; p < pv.n; ++p) {
      pv.load[p] = 0;
      for (std::size_t k = 0; k < loads_.size() && pv.load[p] == 0; ++k) {
        const Load& l = loads_[k];
        bool inside = true;
        for (int d = 0; d < 3; ++d) inside = inside && pv.x[d][p] >= l.lo[d] && pv.x[d][p] <= l.hi[d];
        if (inside) {
          pv.load[p] = std::uint32_t(k + 1);
          mass[k] += pv.mass[p];
        }
      }
    }
    for (std::size_t k = 0; k < loads_.size(); ++k) {
      if (!(mass[k] > 0)) throw std::invalid_argument("load " + std::to_string(k + 1) + " holds no particles");
      for (int d = 0; d < 3; ++d) loads_[k].accel[d] = loads_[k].force[d] / mass[k];
      loads_[k].factor = -1;
    }
  }

  // Writes body_accel (kernels/body_acceleration.hpp) for the loads' ramp factors and the pressure
  // at time t: every step while a pressure acts (it follows the deformation), else only when a
  // load's factor changed.
  void update_body_accelerations(double t) {
    const bool pressurised = pressure_.value != 0 && storage_.has(Attribute::area0);
    if (loads_.empty() && !pressurised) return;
    bool changed = false;
    AlignedVector<T> accel(3 * (loads_.size() + 1), T(0));
    for (std::size_t k = 0; k < loads_.size(); ++k) {
      Load& l = loads_[k];
      const double f = ramp_factor(t, l.ramp_time);
      changed = changed || f != l.factor;
      l.factor = f;
      for (int d = 0; d < 3; ++d) accel[3 * (k + 1) + d] = T(f * l.accel[d]);
    }
    if (!changed && !pressurised) return;
    const T pressure = pressurised ? T(ramp_factor(t, pressure_.ramp_time) * pressure_.value) : T(0);
    backend_.parallel_for(pressurised ? "loads.pressure" : "loads.ramp", storage_.size(),
                          BodyAcceleration<T>{storage_.view(), loads_.empty() ? nullptr : accel.data(), pressure});
  }

  // A linear ramp from zero at t = 0 to one at ramp_time (0: one at once).
  static double ramp_factor(double t, double ramp_time) { return ramp_time > 0 ? std::min(1.0, t / ramp_time) : 1.0; }

  // "constitutive.<model>": a string literal per model type, as launch names must outlive profiles.
  template <class Model>
  static const char* constitutive_launch_name() {
    static const std::string name = std::string("constitutive.") + Model::kName;
    return name.c_str();
  }

  [[noreturn]] void fail(const GuardSummary<T>& s, T dt) {
    const ParticleView<T> pv = storage_.view();
    const std::size_t p = s.offender;
    std::ostringstream msg;
    msg.precision(6);
    msg << "stability guard: step " << steps_ << ", t = " << time_ << " s, dt = " << dt << " s: particle "
        << pv.id[p] << " (material '" << materials_[material_of(p)].info.name << "') "
        << guard_reason_text(s.reason) << ": x = (" << pv.x[0][p] << ", " << pv.x[1][p] << ", " << pv.x[2][p]
        << "), v = (" << pv.v[0][p] << ", " << pv.v[1][p] << ", " << pv.v[2][p]
        << "), J = " << total_J(pv, p);
    if (s.reason == GuardReason::too_fast) msg << ", moved " << s.moved << " m > dx = " << config_.dx << " m";
    throw StabilityError(msg.str());
  }

  SimulationConfig config_;
  Backend backend_;
  ParticleStorage<T> storage_;
  std::vector<Material> materials_;
  std::vector<ColliderBody> colliders_;
  std::vector<DoubleSums<kPenaltySums>> penalty_sums_;  // per collider: this step's penalty force, torque and work
  // The last grid update's parameters: [0] the grid's, [1] contact group B's (a buffer, as kernels
  // read them through a pointer).
  AlignedVector<GridUpdateParams<T>> grid_params_ = AlignedVector<GridUpdateParams<T>>(2);
  AlignedVector<T> reactions_;  // [slot][collider][6] of the last grid update
  int footprint_collider_ = -1;
  AlignedVector<T> footprint_blocks_;  // [slot][16]
  bool budget_enabled_ = false;
  EnergyBudget budget_;
  AlignedVector<T> work_;  // [slot][kWorkKinds] of the last grid update
  FootprintMap footprint_;
  std::vector<Load> loads_;
  struct Pressure {
    double value = 0, ramp_time = 0;  // Pa, s
  } pressure_;
  // The particles added since the last prepare(), as runs of one material each: [begin, begin + count).
  struct StagedRun {
    int material;
    std::size_t begin, count;
  };
  std::vector<StagedRun> staged_;
  AlignedVector<ParticleRun> runs_;         // prepare()'s grouping
  AlignedVector<std::uint32_t> regroup_;    // the permutation prepare() applies
  AlignedVector<std::uint32_t> moves_;      // remove_particles()' moves: destinations, then sources
  BlockCompaction<2> refill_{{"particles.refill.count", "particles.refill.prefix", "particles.refill.write"}};
  SparseGrid<T> grid_;
  // Multi-velocity-field contact: group B's grid, the normals' grid and group B's grid-update
  // buffers; allocated and used only while both groups have particles (contact_active()).
  struct ContactFields {
    std::vector<int> group;  // per material: 0 or 1 (missing: 0)
    Friction<double> friction{};
    SparseGrid<T> grid_b, normals;
    AlignedVector<T> reactions_b, work_b, footprint_b;
  } contact_;
  SparseGrid<T> pool_moments_;  // the pooled collider's mass moments (pool_node), allocated only with one
  ParticleBinning binning_;
  T max_speed_ = T(0);
  // A node with less than this fraction of the lightest particle's mass counts as empty: its
  // weight in any gather is below 1e-10 and its velocity would be rounding noise.
  static constexpr double kEmptyNodeMassFraction = 1e-10;
  T min_node_mass_ = T(0);
  double time_ = 0, last_dt_ = 0;
  long steps_ = 0;
  std::uint32_t next_id_ = 0;  // ids are never reused, so removed and injected particles stay apart
  bool prepared_ = false;
  bool loads_assigned_ = true;  // false after add_load, until the next step assigns particles
};

// Defined out of the class, so that the CPU backends' instances below are compiled only where they
// are instantiated explicitly (engine/simulation_openmp.cpp, engine/simulation_serial.cpp), not in
// every translation unit that steps a simulation.
template <class T, class Backend>
void Simulation<T, Backend>::step(double dt) {
  prepare();
  if (!loads_assigned_) assign_loads();
  update_body_accelerations(time_ + dt);
  const bool quadratic = config_.shape == Shape::quadratic;
  switch (config_.transfer) {
    case Transfer::apic:
      quadratic ? step_impl<QuadraticBSpline<T>, Transfer::apic>(T(dt)) : step_impl<CubicBSpline<T>, Transfer::apic>(T(dt));
      break;
    case Transfer::pic:
      quadratic ? step_impl<QuadraticBSpline<T>, Transfer::pic>(T(dt)) : step_impl<CubicBSpline<T>, Transfer::pic>(T(dt));
      break;
    case Transfer::flip:
      quadratic ? step_impl<QuadraticBSpline<T>, Transfer::flip>(T(dt)) : step_impl<CubicBSpline<T>, Transfer::flip>(T(dt));
      break;
  }
  time_ += dt;
  last_dt_ = dt;
  ++steps_;
}

template <class T, class Backend>
Diagnostics Simulation<T, Backend>::diagnostics() {
  const ParticleView<T> pv = storage_.view();
  const MotionSums s = backend_.parallel_reduce("diagnostics.motion", pv.n, MotionSums{}, MotionTerm<T>{pv},
                                                MergeMotionSums{});
  Diagnostics out;
  out.kinetic_energy = s.ke;
  for (int d = 0; d < 3; ++d) out.momentum[d] = s.p[d];
  out.max_speed = s.max_speed;
  out.min_J = pv.n ? s.min_J : 1.0;
  for (const auto& m : materials_) {
    if (m.range.end == m.range.begin) continue;
    const std::size_t begin = m.range.begin;
    std::visit(
        [&](const auto& model) {
          using Model = std::decay_t<decltype(model)>;
          out.elastic_energy += backend_.parallel_reduce("diagnostics.elastic_energy", m.range.end - begin, 0.0,
                                                         ElasticEnergy<T, Model>{pv, model, begin}, Sum{});
        },
        m.model);
  }
  return out;
}

extern template class Simulation<float, backend::OpenMP>;
extern template class Simulation<double, backend::OpenMP>;
extern template class Simulation<float, backend::Serial>;
extern template class Simulation<double, backend::Serial>;

}  // namespace firn
