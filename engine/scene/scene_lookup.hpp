// Finding a scene by name or path: firn run, check, sweep and study work from any folder, with
// the scenes shipped with firn (installed under PREFIX/share/firn/scenes by cmake --install).
#pragma once

#include <string>
#include <vector>

namespace firn {

// The folder of the shipped scenes for an executable at `executable`: its ../share/firn/scenes
// when that exists (an installed firn), else `fallback` (the source tree's scenes/ for a firn run
// from its build folder).
std::string shipped_scene_folder(const std::string& executable, const std::string& fallback);

// The file a scene argument names, looked up in this order: SCENE as a path, SCENE.toml,
// scenes/SCENE.toml (both relative to the current folder), then SCENE.toml in `shipped_folder`.
// Throws SceneError naming every place it looked when none is a file.
std::string find_scene(const std::string& scene, const std::string& shipped_folder);

struct ShippedScene {
  std::string name;     // the file name without .toml: what `firn run NAME` takes
  std::string summary;  // the first comment line of the file, without the leading "# " and name
};

// The scenes in `folder` (*.toml), sorted by name; empty when the folder does not exist.
std::vector<ShippedScene> list_scenes(const std::string& folder);

}  // namespace firn
