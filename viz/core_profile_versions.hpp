// The core-profile versions both context kinds try, best first (DESIGN.md section 7 asks for 4.5;
// the renderer's shaders need 3.3).
#pragma once

namespace firn::viz {

struct GlVersion {
  int major, minor;
};
inline constexpr GlVersion kCoreProfileVersions[] = {{4, 5}, {4, 3}, {4, 1}, {3, 3}};

}  // namespace firn::viz
