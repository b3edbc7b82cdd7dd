// The pooled collider's mass moments (pool_node, kernels/pooled_contact.hpp): the contact normals'
// scatter with one contact group (kernels/step/contact_normals.hpp), from only those particle blocks
// whose particles can reach a block near the collider, the only blocks whose moments the pool reads
// (kernels/grid_update.hpp, kernels/step/contact_pool_sums.hpp). A particle is binned to the block
// of its stencil's base node (engine/particle_binning.hpp) and adds to nodes from there to at most
// three past it (a support of three or four nodes), so every block it reaches is b or one block
// further along each axis. b's box widened by a block holds each of those blocks' boxes, and
// colliders_near_block is monotone in the box, so b is kept wherever one of them is near the
// collider. Every backend asks keeps(b) before it scatters block b (kernels/backend/scatter_skip.hpp).
#pragma once

#include <cstdint>

#include "kernels/grid_update.hpp"
#include "kernels/hd.hpp"
#include "kernels/step/contact_normals.hpp"

namespace firn {

template <class T, class ShapeT>
struct ContactPoolMomentsScatter : ContactNormalScatter<T, ShapeT> {
  const GridUpdateParams<T>* params;  // posed for this step's grid update
  int collider;

  FIRN_HD bool keeps(std::uint32_t b) const {
    int block[3];
    this->grid.box.coords(b, block);
    return colliders_near_block(block, *params, kBlockSize) >> collider & 1u;
  }
};

}  // namespace firn
