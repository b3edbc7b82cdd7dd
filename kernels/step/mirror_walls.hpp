// Mirror walls (issue 19 item 3): sticky and slip domain walls imposed through mirrored ghost nodes,
// so that a body's boundary on the wall keeps the whole B-spline support of the particles next to
// it instead of losing the half beyond the wall.
//
// A mirror wall's plane is the innermost node row of its band (index width - 1 from the low face,
// nodes - width from the high one); the band's other rows are ghost nodes. The body on the inner
// side is extended across the plane by its mirror image, which P2G never sees; its contributions
// to a node equal the body's own contributions to the node's image across the plane, with the
// momentum's components multiplied by a sign vector S:
//   slip (a symmetry plane):    S = -1 along the normal, +1 along the plane. The image is the
//                               mirrored body, exact for any material and motion;
//   sticky (a clamped plane):   S = -1 for every component: the velocity field is extended by its
//                               odd image, v(x') = -v(x), which vanishes on the plane. It is exact
//                               for motion along the normal in a uniaxial stress (the vibrating bar)
//                               and for linear fields; in shear it is an approximation.
// Both are the image (ghost) particle method of SPH walls (Morris, Fox and Zhu 1997, J. Comput.
// Phys. 136, 214-226: ghost particles with the fluid's velocity reversed for no-slip), done on the
// grid: folding the ghost rows onto their inner images is the same as scattering the image
// particles. The grid velocity a node gets is then the one of the whole extended field, and the
// gradient at a particle next to the wall is consistent; with the support cut at the wall (plain
// walls), the force on the nodes next to a stressed boundary misses the image's share, an O(dx)
// error (Steffen et al. 2008, CMES 31, 107-127, on boundary treatments).
//
// Two passes over the active block slots:
//   MirrorFold    after P2G, before the grid update: every node outside all mirror bands' ghost
//                 rows adds the P2G sums (mass, momentum, FLIP's old momentum) of its images,
//                 S-signed, over every combination of the axes it is near a mirror plane in (an
//                 edge node has three images, a corner node seven). A node on a plane is its own
//                 image there: its sums double, and the S-signed components cancel, as FLIP's old
//                 velocity must for the plane's velocity change to be the whole body's. The grid
//                 update adds dt g to the combined node, whereas the image feels S g: the fold adds
//                 the difference dt m_image (S g - g) to the momentum.
//   MirrorGhosts  after the grid update: every ghost node takes the S-signed velocity (and FLIP
//                 old velocity) of its inner image, so that G2P reads the extended field.
// A collider reaching into a band's ghost rows acts on velocities that MirrorGhosts then replaces,
// so its reaction there is meaningless: scenes keep colliders out of mirror bands (docs/scenes.md).
// Each pass writes only nodes that no other node of the pass reads (inner nodes in the fold, ghost
// nodes after the update), so blocks run in any order and give the same bits. Images in blocks that hold
// no particles contribute nothing (their sums are zero).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "kernels/block_window.hpp"
#include "kernels/boundary_conditions.hpp"
#include "kernels/grid_geometry.hpp"
#include "kernels/grid_slots.hpp"
#include "kernels/hd.hpp"
#include "kernels/transfer.hpp"

namespace firn {

// The mirror walls of the six faces (-x, +x, -y, +y, -z, +z).
template <class T>
struct MirrorPlanes {
  bool active[6] = {false, false, false, false, false, false};
  int plane[6] = {0, 0, 0, 0, 0, 0};  // node index of the plane along the face's axis
  int reach[6] = {0, 0, 0, 0, 0, 0};  // ghost rows beyond the plane: width - 1
  T sign[6][3] = {};                   // S per momentum component
  int nodes[3] = {0, 0, 0};            // node count per axis

  FIRN_HD bool any() const { return active[0] || active[1] || active[2] || active[3] || active[4] || active[5]; }
  // The face on axis d whose ghost rows hold node index i, or -1.
  FIRN_HD int ghost_face(int d, int i) const {
    if (active[2 * d] && i < plane[2 * d]) return 2 * d;
    if (active[2 * d + 1] && i > plane[2 * d + 1]) return 2 * d + 1;
    return -1;
  }
  // The face on axis d of whose ghost rows node index i is the inner image (the plane's row is its
  // own image), or -1.
  FIRN_HD int image_face(int d, int i) const {
    const int lo = 2 * d, hi = 2 * d + 1;
    if (active[lo] && i >= plane[lo] && i <= plane[lo] + reach[lo]) return lo;
    if (active[hi] && i <= plane[hi] && i >= plane[hi] - reach[hi]) return hi;
    return -1;
  }
};

// Why a wall with `mirror` set cannot be one, on an axis of `nodes` nodes, or "" if it can: a mirror
// wall is sticky, or slip without friction (a symmetry plane), whose band holds its plane and at
// least the one ghost row that the quadratic and cubic B-splines of the particles inside reach,
// in a domain wider than two bands. (Host only: the scene reader and Simulation ask it.)
inline std::string mirror_wall_error(WallType type, int width, double friction, int nodes) {
  if (type != WallType::sticky && type != WallType::slip) return "a mirror wall is sticky or slip";
  if (type == WallType::slip && friction != 0)
    return "a slip mirror wall is a symmetry plane and takes no friction (set friction = 0)";
  if (width < 2) return "a mirror wall needs width >= 2: its plane and a row of ghost nodes";
  if (2 * width + 1 > nodes) return "the domain is too narrow for two mirror bands of this width";
  return "";
}

// The mirror planes of the walls with `mirror` set (mirror_wall_error has passed them).
template <class T, class U>
MirrorPlanes<T> mirror_planes(const Wall<U>* walls, const int nodes[3]) {
  MirrorPlanes<T> m;
  for (int d = 0; d < 3; ++d) m.nodes[d] = nodes[d];
  for (int f = 0; f < 6; ++f) {
    const int d = f / 2;
    if (!walls[f].mirror) continue;
    m.active[f] = true;
    m.reach[f] = walls[f].width - 1;
    m.plane[f] = f % 2 == 0 ? walls[f].width - 1 : nodes[d] - walls[f].width;
    for (int r = 0; r < 3; ++r) m.sign[f][r] = walls[f].type == WallType::slip && r != d ? T(1) : T(-1);
  }
  return m;
}

// The grid channel of the fold's c-th sum: 0 the mass, 1-3 the momentum, 4-6 FLIP's old momentum.
template <Transfer kTransfer>
FIRN_HD int channel(int c) {
  using Ch = GridChannels<kTransfer>;
  return c == 0 ? Ch::kMass : c <= 3 ? Ch::kVelocity + c - 1 : Ch::kOldVelocity + c - 4;
}

// Node (i, j, k)'s channel 0 in the sparse grid (channel c at + c kBlockNodes), or null where its
// block is inactive or it lies off the grid.
template <class T>
FIRN_HD T* grid_node(const SparseGridView<T>& grid, const int n[3], const int nodes[3]) {
  for (int d = 0; d < 3; ++d)
    if (n[d] < 0 || n[d] >= nodes[d]) return nullptr;
  const std::int32_t slot =
      grid.block_map[grid.box.id(n[0] >> kBlockShift, n[1] >> kBlockShift, n[2] >> kBlockShift)];
  if (slot < 0) return nullptr;
  const int mask = kBlockSize - 1;
  return grid.data + std::size_t(slot) * std::size_t(grid.channels) * kBlockNodes +
         local_node(n[0] & mask, n[1] & mask, n[2] & mask);
}

template <class T, Transfer kTransfer>
struct MirrorFold {
  GridSlotsView<T> slots;
  SparseGridView<T> grid;
  MirrorPlanes<T> planes;
  T dt;
  T gravity[3];

  FIRN_HD void operator()(std::size_t s) const {
    T* data = slots.slot_data(s);
    const int* block = slots.slot_coords(s);
    for (int l = 0; l < kBlockNodes; ++l) {
      int n[3];
      block_node(block, l, n);
      int faces[3], axes = 0;
      bool ghost = false;
      for (int d = 0; d < 3; ++d) {
        ghost = ghost || planes.ghost_face(d, n[d]) >= 0;
        faces[d] = planes.image_face(d, n[d]);
      }
      if (ghost) continue;
      for (int d = 0; d < 3; ++d) axes |= faces[d] >= 0 ? 1 << d : 0;
      if (axes == 0) continue;
      // The sums, read before any is written: a node on a plane is its own image there.
      constexpr int kSums = kTransfer == Transfer::flip ? 7 : 4;  // mass, momentum, FLIP's old momentum
      T sum[kSums];
      for (int c = 0; c < kSums; ++c) sum[c] = data[channel<kTransfer>(c) * kBlockNodes + l];
      for (int combo = 1; combo < 8; ++combo) {  // every non-empty subset of the near axes
        if ((combo & axes) != combo) continue;
        int image[3] = {n[0], n[1], n[2]};
        T sign[3] = {T(1), T(1), T(1)};
        for (int d = 0; d < 3; ++d)
          if (combo & (1 << d)) {
            image[d] = 2 * planes.plane[faces[d]] - n[d];
            for (int r = 0; r < 3; ++r) sign[r] *= planes.sign[faces[d]][r];
          }
        const T* src = grid_node(grid, image, planes.nodes);
        if (!src) continue;
        const T m = src[channel<kTransfer>(0) * kBlockNodes];
        sum[0] += m;
        for (int c = 1; c < kSums; ++c) {
          const int r = (c - 1) % 3;
          sum[c] += sign[r] * src[channel<kTransfer>(c) * kBlockNodes];
          if (c <= 3) sum[c] += dt * m * (sign[r] - T(1)) * gravity[r];
        }
      }
      for (int c = 0; c < kSums; ++c) data[channel<kTransfer>(c) * kBlockNodes + l] = sum[c];
    }
  }
};

template <class T, Transfer kTransfer>
struct MirrorGhosts {
  GridSlotsView<T> slots;
  SparseGridView<T> grid;
  MirrorPlanes<T> planes;

  FIRN_HD void operator()(std::size_t s) const {
    using Ch = GridChannels<kTransfer>;
    T* data = slots.slot_data(s);
    const int* block = slots.slot_coords(s);
    for (int l = 0; l < kBlockNodes; ++l) {
      int n[3], image[3];
      block_node(block, l, n);
      T sign[3] = {T(1), T(1), T(1)};
      bool ghost = false;
      for (int d = 0; d < 3; ++d) {
        const int f = planes.ghost_face(d, n[d]);
        image[d] = f >= 0 ? 2 * planes.plane[f] - n[d] : n[d];
        if (f < 0) continue;
        ghost = true;
        for (int r = 0; r < 3; ++r) sign[r] *= planes.sign[f][r];
      }
      if (!ghost) continue;
      const T* src = grid_node(grid, image, planes.nodes);
      for (int r = 0; r < 3; ++r)
        data[(Ch::kVelocity + r) * kBlockNodes + l] = src ? sign[r] * src[(Ch::kVelocity + r) * kBlockNodes] : T(0);
      if (kTransfer == Transfer::flip)
        for (int r = 0; r < 3; ++r)
          data[(Ch::kOldVelocity + r) * kBlockNodes + l] =
              src ? sign[r] * src[(Ch::kOldVelocity + r) * kBlockNodes] : T(0);
    }
  }
};

}  // namespace firn
