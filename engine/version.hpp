// firn's version, as `firn --version` prints it and checkpoints record it: the project's version
// and, in a build configured from a git checkout, its commit.
#pragma once

namespace firn {

const char* firn_version();

}  // namespace firn
