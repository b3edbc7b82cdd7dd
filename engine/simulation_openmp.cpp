// Simulation on the OpenMP backend, compiled once for both precisions (engine/simulation.hpp declares
// these instances extern).
#include "engine/simulation.hpp"

namespace firn {

template class Simulation<float, backend::OpenMP>;
template class Simulation<double, backend::OpenMP>;

}  // namespace firn
