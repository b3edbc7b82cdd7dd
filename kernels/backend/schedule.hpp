// How a backend distributes a launch's items: `uniform` for many cheap items of equal cost
// (particles), `uneven` for items of very different cost (a surface's cells), `blocks` for grid
// blocks: fewer, heavier items whose cost can differ (a block near a collider evaluates its
// distance field at every node, the others only scale their momenta), and `parts` for a job cut
// into one part per thread (backend.threads() items), each on its own thread however few they are.
#pragma once

namespace firn::backend {

enum class Schedule { uniform, uneven, blocks, parts };

}  // namespace firn::backend
