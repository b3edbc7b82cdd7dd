// Reads and validates a scene file (DESIGN.md section 5) against the key table of
// scene_schema.hpp. Every fault (TOML syntax, unknown key with a suggestion, wrong type, missing
// value, a unit of the wrong quantity, a non-physical value, a body outside the domain or with no
// particles) is a SceneError whose message is one line "FILE:LINE:COLUMN: KEY: what is wrong".
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "engine/scene/scene.hpp"

namespace firn {

struct SceneError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct SceneOptions {
  std::vector<std::string> overrides;  // "a.b.c=value", as given to --set
  bool preview = false;                // dx doubled, particles per cell and frames reduced
};

struct LoadedScene {
  SceneSpec spec;
  std::string resolved_toml;  // every value used, in SI, defaults filled in: re-runnable as is
};

LoadedScene load_scene(const std::string& path, const SceneOptions& options);
// The same for a scene's text; `path` names it in messages and gives the scene its name.
LoadedScene load_scene_text(const std::string& text, const std::string& path, const SceneOptions& options);

}  // namespace firn
