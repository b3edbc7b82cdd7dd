// Particle attributes, declared once (DESIGN.md section 2, rule 4). Storage, views, output fields
// and renderer attributes are all derived from this list; code accesses attributes by name.
// An attribute's layout is `columns`, one contiguous array per scalar component (structure of
// arrays, the rule), or `record`, its n values of a particle side by side in one array (value c of
// particle p at [n p + c]). A record is for an attribute that kernels only read and write one whole
// particle at a time, in the short vectors of a stencil row: C, which G2P writes and P2G reads as
// the three 4-lane columns P2G scatters (issue 15; docs/performance.md, "C as a record").
#pragma once

#include <cstddef>
#include <cstdint>

namespace firn {

// X(name, values per particle, scalar kind (Real or Index), allocation (always or on_demand),
//   layout (columns or record), description)
#define FIRN_PARTICLE_ATTRIBUTES(X)                                                                       \
  X(x, 3, Real, always, columns, "position (m)")                                                          \
  X(v, 3, Real, always, columns, "velocity (m/s)")                                                        \
  X(C, 12, Real, on_demand, record,                                                                       \
    "affine velocity field, the MLS velocity gradient (1/s); APIC. Column k of C at 4k + 1 .. 4k + 3 "    \
    "(row r at 4k + 1 + r), 4k zero: P2G's lane order (mass, momentum)")                                   \
  X(F, 9, Real, always, columns, "deformation gradient, row-major")                                       \
  X(tau, 6, Real, always, columns, "Kirchhoff stress tau = J sigma (Pa), symmetric: xx yy zz xy yz zx")   \
  X(mass, 1, Real, always, columns, "mass (kg)")                                                          \
  X(vol0, 1, Real, always, columns, "rest volume (m^3)")                                                  \
  X(id, 1, Index, always, columns, "particle id, stable when particles are reordered")                    \
  X(x0, 3, Real, on_demand, columns, "rest position (m)")                                                 \
  X(body_accel, 3, Real, on_demand, columns, "external body acceleration (m/s^2)")                        \
  X(load, 1, Index, on_demand, columns, "1 + index of the load the particle carries, 0 for none")        \
  X(area0, 3, Real, on_demand, columns, "rest area vector N dA of a pressurised surface (m^2), N into the body") \
  X(alpha, 1, Real, on_demand, columns, "equivalent plastic strain (J2 plasticity)")                      \
  X(Jp, 1, Real, on_demand, columns, "plastic volume ratio J_P = det F_P; F then holds the elastic part")

// Arrays per attribute and values per particle in each: n and 1 for columns, 1 and n for a record.
#define FIRN_ARRAYS_columns(n) n
#define FIRN_ARRAYS_record(n) 1
#define FIRN_WIDTH_columns(n) 1
#define FIRN_WIDTH_record(n) n

enum class Attribute {
#define FIRN_ATTRIBUTE_ENUM(name, n, kind, alloc, layout, doc) name,
  FIRN_PARTICLE_ATTRIBUTES(FIRN_ATTRIBUTE_ENUM)
#undef FIRN_ATTRIBUTE_ENUM
      count
};

// The pointer type of an attribute: T* for one array, T* [n] for n arrays.
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
#define FIRN_VIEW_MEMBER(name, n, kind, alloc, layout, doc) \
  typename Columns<FIRN_SCALAR_##kind(T), FIRN_ARRAYS_##layout(n)>::type name;
  FIRN_PARTICLE_ATTRIBUTES(FIRN_VIEW_MEMBER)
#undef FIRN_VIEW_MEMBER
  std::size_t n;
};

}  // namespace firn
