// Fragments: the connected clusters of particles, two particles linked when closer than `link`
// (issue 16, item 5: does a snowball break into pieces that fly apart?). MPM particles interact
// only through grid nodes, a quadratic B-spline reaching 1.5 cells from its particle; the scene
// default link is 1.5 cells, above the particle spacing at any particles_per_cell (a link of one
// cell splits a one-particle-per-cell lattice into single particles). Clusters of
// fewer than `min_particles` (spray) are not counted as fragments. A uniform hash grid of cell
// `link` finds the neighbours (27 cells each) and a union-find with path halving joins them
// (Tarjan, J. ACM 22(2):215, 1975): O(n) expected.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace firn {

struct FragmentCount {
  std::size_t fragments = 0;  // clusters of at least min_particles
  std::size_t largest = 0;    // particles in the largest cluster
};

FragmentCount count_fragments(const std::vector<std::array<double, 3>>& x, double link, std::size_t min_particles);

}  // namespace firn
