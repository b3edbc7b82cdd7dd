// The stability study's own small problems, as scene files (written under DIR/scenes/ so that any
// row of stability.csv can be re-run with `firn run DIR/scenes/NAME.toml`), and the materials they
// are run with.
#pragma once

#include <string>
#include <vector>

#include "engine/scene/scene_reader.hpp"

namespace firn::study {

struct StudyMaterial {
  std::string name;   // a short label for stability.csv
  std::string table;  // the body of a [materials.NAME] table, TOML
};

// The thesis' materials: both snows (Table 4.3), the tire rubber (Mooney-Rivlin, E = 1e7 Pa,
// nu = 0.49) and a compressible neo-Hookean solid (the cube_drop reference: E = 1e5 Pa, nu = 0.3,
// 1000 kg/m^3).
std::vector<StudyMaterial> thesis_materials();

// Rubber with the thesis' E = 1e7 Pa and 930 kg/m^3 at Poisson's ratio nu, model mooney_rivlin or
// neo_hookean.
StudyMaterial rubber(const std::string& model, double nu);

// A ball of radius 20 mm (dx 4 mm, 8 particles per cell: about 4,000 particles) thrown at 5 m/s
// into a fixed plane wall 10 mm away (separating contact, Coulomb 0.3), under gravity, for
// end_time.
std::string ball_wall_scene(const StudyMaterial& m, double end_time);

// A 40 x 20 x 40 mm block (dx 4 mm, 8 particles per cell: 4,000 particles) on a sticky floor,
// squeezed by its own weight under a body force of 2000 m/s^2 (about 200 g): a smooth pressure that
// grows linearly from zero at the top to rho g h = 37 kPa at the floor (for 930 kg/m^3).
std::string squeezed_block_scene(const StudyMaterial& m, double end_time);

// A 24 mm cube (dx 4 mm, 8 particles per cell: 1,728 particles) of thesis hard snow at rest on a
// sticky floor at y = 0 (the domain's floor is 3 cells below), under gravity.
std::string resting_block_scene(double end_time);

// Writes DIR/scenes/NAME.toml and loads it.
LoadedScene write_and_load_scene(const std::string& dir, const std::string& name, const std::string& toml,
                                 const SceneOptions& options = {});

}  // namespace firn::study
