// Solid shapes that bodies are filled from (DESIGN.md section 5): sphere, axis-aligned box,
// cylinder along a coordinate axis, and the union or difference (first part minus the others) of
// such shapes, nested to any depth.
#pragma once

#include <vector>

#include "engine/particle_fill.hpp"

namespace firn {

struct BodyShape {
  enum class Kind { sphere, box, cylinder, union_of, difference_of };
  Kind kind = Kind::sphere;
  Point center = {0, 0, 0};  // sphere, cylinder
  double radius = 0;         // sphere, cylinder
  Point min = {0, 0, 0}, max = {0, 0, 0};  // box
  int axis = 1;              // cylinder: 0 x, 1 y, 2 z
  double length = 0;         // cylinder, along its axis, centred on `center`
  std::vector<BodyShape> parts;  // union_of, difference_of

  bool contains(const Point& p) const;
  // An axis-aligned box that holds the shape.
  void bounds(Point& lo, Point& hi) const;
};

}  // namespace firn
