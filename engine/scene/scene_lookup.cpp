#include "engine/scene/scene_lookup.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "engine/scene/scene_reader.hpp"

namespace firn {

namespace fs = std::filesystem;

std::string shipped_scene_folder(const std::string& executable, const std::string& fallback) {
  const fs::path installed = fs::path(executable).parent_path() / ".." / "share" / "firn" / "scenes";
  std::error_code ec;
  if (fs::is_directory(installed, ec)) return fs::weakly_canonical(installed, ec).string();
  return fallback;
}

std::string find_scene(const std::string& scene, const std::string& shipped_folder) {
  std::vector<std::string> candidates{scene, scene + ".toml"};
  // A bare name may also be a shipped scene; a path with folders names one file only.
  if (scene.find('/') == std::string::npos) {
    candidates.push_back("scenes/" + scene + ".toml");
    if (!shipped_folder.empty()) candidates.push_back(shipped_folder + "/" + scene + ".toml");
  }
  std::error_code ec;
  for (const std::string& c : candidates)
    if (fs::is_regular_file(c, ec)) return c;
  std::string looked;
  for (const std::string& c : candidates) looked += (looked.empty() ? "" : ", ") + c;
  throw SceneError(scene + ": no such scene (looked for " + looked +
                   "; `firn help scenes` lists the shipped scenes)");
}

std::vector<ShippedScene> list_scenes(const std::string& folder) {
  std::vector<ShippedScene> scenes;
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(folder, ec)) {
    if (e.path().extension() != ".toml" || !e.is_regular_file(ec)) continue;
    ShippedScene s{e.path().stem().string(), ""};
    std::ifstream in(e.path());
    std::string first;
    if (std::getline(in, first) && first.rfind("# ", 0) == 0) {
      s.summary = first.substr(2);
      if (s.summary.rfind(s.name + ": ", 0) == 0) s.summary.erase(0, s.name.size() + 2);
    }
    scenes.push_back(std::move(s));
  }
  std::sort(scenes.begin(), scenes.end(), [](const ShippedScene& a, const ShippedScene& b) { return a.name < b.name; });
  return scenes;
}

}  // namespace firn
