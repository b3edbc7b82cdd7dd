// A unit cube domain with no walls and a coarse grid (dx 0.05): the tests' open space for a body,
// where nothing but what a test adds (gravity, a collider, a load) acts on it.
#pragma once

#include "engine/simulation.hpp"

namespace firn {

inline SimulationConfig open_box() {
  SimulationConfig c;
  c.domain_min = {0, 0, 0};
  c.domain_max = {1, 1, 1};
  c.dx = 0.05;
  for (auto& w : c.walls) w = {WallType::none, 0, 0};
  return c;
}

}  // namespace firn
