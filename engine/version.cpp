#include "engine/version.hpp"

namespace firn {

// FIRN_VERSION_TEXT is set by CMakeLists.txt at configure time.
const char* firn_version() { return FIRN_VERSION_TEXT; }

}  // namespace firn
