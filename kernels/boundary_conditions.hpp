// Velocity boundary conditions at a wall with outward-from-wall normal n (pointing into the
// material), applied to a grid velocity relative to the wall:
//   sticky:   v = 0;
//   slip:     the normal component is removed in both directions;
//   separate: the normal component is removed only when approaching (v.n < 0), so material can
//             leave the wall (Stomakhin et al. 2013, Sec. 8);
// slip and separate apply friction when approaching: v_t <- v_t max(0, 1 - mu(|v_t|) |v_n| / |v_t|)
// with mu from kernels/friction.hpp evaluated at the trial slip speed |v_t| (DESIGN.md section 4,
// "Friction").
#pragma once

#include <cmath>
#include <cstdint>

#include "kernels/friction.hpp"
#include "kernels/hd.hpp"

namespace firn {

enum class WallType : std::uint8_t { none, sticky, slip, separate };

template <class T>
struct Wall {
  WallType type = WallType::none;
  int width = 0;  // the wall acts on the nodes closer than `width` cells to the domain face
  T friction = 0;  // Coulomb coefficient mu
  bool mirror = false;  // domain walls: imposed through mirrored ghost nodes (kernels/step/mirror_walls.hpp)
};

template <class T>
FIRN_HD void apply_wall(T v[3], const T n[3], WallType type, const Friction<T>& friction) {
  if (type == WallType::none) return;
  if (type == WallType::sticky) {
    v[0] = v[1] = v[2] = T(0);
    return;
  }
  const T vn = v[0] * n[0] + v[1] * n[1] + v[2] * n[2];
  if (type == WallType::separate && vn >= T(0)) return;
  T vt[3] = {v[0] - vn * n[0], v[1] - vn * n[1], v[2] - vn * n[2]};
  if (vn < T(0) && friction.mu > T(0)) {
    const T vt_norm = std::sqrt(vt[0] * vt[0] + vt[1] * vt[1] + vt[2] * vt[2]);
    const T keep = friction.slip_kept(vt_norm, -vn);
    for (int d = 0; d < 3; ++d) vt[d] *= keep;
  }
  for (int d = 0; d < 3; ++d) v[d] = vt[d];
}

// Coulomb friction with coefficient mu.
template <class T>
FIRN_HD void apply_wall(T v[3], const T n[3], WallType type, T mu) {
  apply_wall(v, n, type, Friction<T>{FrictionLaw::coulomb, mu});
}

}  // namespace firn
