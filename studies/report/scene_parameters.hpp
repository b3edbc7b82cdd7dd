// The key parameters of a run's scene for its report: the sections of scene.resolved.toml that say
// what was simulated ([simulation], each [materials.NAME], [[bodies]], [[colliders]], [tire],
// [conveyor]), every default filled in. The rendering, walls and metrics settings are left to the
// linked file.
#pragma once

#include <string>

namespace firn::report {

// HTML tables of those sections of a resolved scene's TOML text (values as TOML writes them, text
// unquoted); throws std::runtime_error when the text is not TOML.
std::string scene_parameters_html(const std::string& resolved_toml);

}  // namespace firn::report
