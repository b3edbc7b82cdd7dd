// How a backend distributes a launch's items: `uniform` for items of equal cost (particles),
// `uneven` for items of very different cost (grid blocks with different particle counts).
#pragma once

namespace firn::backend {

enum class Schedule { uniform, uneven };

}  // namespace firn::backend
