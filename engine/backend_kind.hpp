// The backends a run can choose at run time (`--backend serial|openmp|cuda`; DESIGN.md section 2):
// serial (one thread, the reference), openmp (the CPU default) and cuda (an NVIDIA GPU, in builds
// with FIRN_CUDA). The engine's templates take the backend type; this is its name on the
// command line and in summary.json.
#pragma once

#include <string>

namespace firn {

enum class BackendKind { serial, openmp, cuda };

const char* backend_name(BackendKind kind);

// The backend called `name`; throws std::invalid_argument for another name.
BackendKind backend_named(const std::string& name);

// Why `kind` cannot run in this build on this machine ("this build has no CUDA backend", "no CUDA
// device", ...), or an empty string when it can.
std::string backend_unavailable(BackendKind kind);

}  // namespace firn
