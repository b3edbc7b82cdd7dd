// Simulation on the Serial backend, compiled once for both precisions (engine/simulation.hpp declares
// these instances extern).
#include "engine/simulation.hpp"

namespace firn {

template class Simulation<float, backend::Serial>;
template class Simulation<double, backend::Serial>;

}  // namespace firn
