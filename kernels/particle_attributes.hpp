// Particle attributes, declared once (DESIGN.md section 2, rule 4). Storage, views, output fields
// and renderer attributes are all derived from this list; code accesses attributes by name.
// Every attribute is stored as one contiguous array per scalar component (structure of arrays).
#pragma once

#include <cstddef>
#include <cstdint>

namespace firn {

// X(name, components, scalar kind (Real or Index), allocation (always or on_demand), description)
#define FIRN_PARTICLE_ATTRIBUTES(X)                                                                    \
  X(x, 3, Real, always, "position (m)")                                                                \
  X(v, 3, Real, always, "velocity (m/s)")                                                              \
  X(C, 9, Real, on_demand, "affine velocity field, the MLS velocity gradient (1/s), row-major; APIC") \
  X(F, 9, Real, always, "deformation gradient, row-major")                                             \
  X(tau, 6, Real, always, "Kirchhoff stress tau = J sigma (Pa), symmetric: xx yy zz xy yz zx")         \
  X(mass, 1, Real, always, "mass (kg)")                                                                \
  X(vol0, 1, Real, always, "rest volume (m^3)")                                                        \
  X(id, 1, Index, always, "particle id, stable when particles are reordered")                          \
  X(x0, 3, Real, on_demand, "rest position (m)")                                                       \
  X(body_accel, 3, Real, on_demand, "external body acceleration (m/s^2)")                              \
  X(load, 1, Index, on_demand, "1 + index of the load the particle carries, 0 for none")              \
  X(area0, 3, Real, on_demand, "rest area vector N dA of a pressurised surface (m^2), N into the body") \
  X(alpha, 1, Real, on_demand, "equivalent plastic strain (J2 plasticity)")                            \
  X(Jp, 1, Real, on_demand, "plastic volume ratio J_P = det F_P; F then holds the elastic part")

enum class Attribute {
#define FIRN_ATTRIBUTE_ENUM(name, n, kind, alloc, doc) name,
  FIRN_PARTICLE_ATTRIBUTES(FIRN_ATTRIBUTE_ENUM)
#undef FIRN_ATTRIBUTE_ENUM
      count
};

// The column pointer type of an attribute: T* for one component, T* [n] for n components.
template <class S, int N>
struct Columns {
  using type = S* [N];
};
template <class S>
struct Columns<S, 1> {
  using type = S*;
};

#define FIRN_SCALAR_Real(T) T
#define FIRN_SCALAR_Index(T) std::uint32_t

// A trivially copyable view of the particle arrays, handed to kernels. Attributes that were not
// allocated (on_demand ones nobody asked for) are null.
template <class T>
struct ParticleView {
#define FIRN_VIEW_MEMBER(name, n, kind, alloc, doc) typename Columns<FIRN_SCALAR_##kind(T), n>::type name;
  FIRN_PARTICLE_ATTRIBUTES(FIRN_VIEW_MEMBER)
#undef FIRN_VIEW_MEMBER
  std::size_t n;
};

}  // namespace firn
