#include "studies/stability/stability_scenes.hpp"

#include <cstdio>

#include "engine/output/atomic_file.hpp"

namespace firn::study {

std::vector<StudyMaterial> thesis_materials() {
  return {{"hard_snow", "preset = \"thesis_hard_snow\"\n"},
          {"soft_snow", "preset = \"thesis_soft_snow\"\n"},
          {"rubber_mooney_rivlin_nu0.49", "preset = \"thesis_tire_rubber\"\n"},
          {"neo_hookean", "model = \"neo_hookean\"\ndensity = 1000\nE = 1e5\nnu = 0.3\n"}};
}

StudyMaterial rubber(const std::string& model, double nu) {
  char table[160], name[64];
  std::snprintf(table, sizeof table, "model = \"%s\"\ndensity = 930\nE = 1e7\nnu = %.6g\n", model.c_str(), nu);
  std::snprintf(name, sizeof name, "rubber_%s_nu%.6g", model.c_str(), nu);
  return {name, table};
}

namespace {

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

}  // namespace

std::string ball_wall_scene(const StudyMaterial& m, double end_time) {
  return "# firn study stability: a ball thrown into a wall (" + m.name + ")\n"
         "[simulation]\n"
         "domain_min = [-0.06, -0.04, -0.04]\n"
         "domain_max = [0.04, 0.04, 0.04]\n"
         "dx = 0.004\n"
         "particles_per_cell = 8\n"
         "end_time = " + number(end_time) + "\n"
         "frame_interval = " + number(end_time) + "\n\n"
         "[materials.ball]\n" + m.table + "\n"
         "[[bodies]]\n"
         "material = \"ball\"\n"
         "shape = \"sphere\"\n"
         "center = [-0.025, 0, 0]\n"
         "radius = 0.02\n"
         "velocity = [5, 0, 0]\n\n"
         "[[colliders]]\n"
         "name = \"wall\"\n"
         "shape = \"plane\"\n"
         "point = [0.005, 0, 0]\n"
         "normal = [-1, 0, 0]\n"
         "boundary = \"separate\"\n"
         "friction = 0.3\n";
}

std::string squeezed_block_scene(const StudyMaterial& m, double end_time) {
  return "# firn study stability: a block squeezed on a floor (" + m.name + ")\n"
         "[simulation]\n"
         "domain_min = [-0.04, -0.012, -0.04]\n"
         "domain_max = [0.04, 0.04, 0.04]\n"
         "dx = 0.004\n"
         "particles_per_cell = 8\n"
         "end_time = " + number(end_time) + "\n"
         "frame_interval = " + number(end_time) + "\n"
         "gravity = [0, -2000, 0]\n\n"
         "[materials.block]\n" + m.table + "\n"
         "[[bodies]]\n"
         "material = \"block\"\n"
         "shape = \"box\"\n"
         "min = [-0.02, 0.0, -0.02]\n"
         "max = [0.02, 0.02, 0.02]\n\n"
         "[[colliders]]\n"
         "name = \"floor\"\n"
         "shape = \"plane\"\n"
         "point = [0, 0, 0]\n"
         "normal = [0, 1, 0]\n"
         "boundary = \"sticky\"\n";
}

std::string resting_block_scene(double end_time) {
  return "# firn study stability: a block of thesis hard snow resting on a floor\n"
         "[simulation]\n"
         "domain_min = [-0.032, -0.012, -0.032]\n"
         "domain_max = [0.032, 0.048, 0.032]\n"
         "dx = 0.004\n"
         "particles_per_cell = 8\n"
         "end_time = " + number(end_time) + "\n"
         "frame_interval = " + number(end_time) + "\n\n"
         "[materials.snow]\n"
         "preset = \"thesis_hard_snow\"\n\n"
         "[[bodies]]\n"
         "material = \"snow\"\n"
         "shape = \"box\"\n"
         "min = [-0.012, 0.0, -0.012]\n"
         "max = [0.012, 0.024, 0.012]\n\n"
         "[[colliders]]\n"
         "name = \"floor\"\n"
         "shape = \"plane\"\n"
         "point = [0, 0, 0]\n"
         "normal = [0, 1, 0]\n"
         "boundary = \"sticky\"\n";
}

LoadedScene write_and_load_scene(const std::string& dir, const std::string& name, const std::string& toml,
                                 const SceneOptions& options) {
  make_directories(dir + "/scenes");
  const std::string path = dir + "/scenes/" + name + ".toml";
  write_file_atomically(path, toml);
  return load_scene(path, options);
}

}  // namespace firn::study
