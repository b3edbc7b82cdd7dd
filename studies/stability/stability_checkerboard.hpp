// A pressure checkerboard indicator for nearly incompressible solids: the odd-even pressure mode
// that a grid too coarse for the incompressibility constraint leaves in a particle field (volumetric
// locking's companion; Hughes, "The Finite Element Method", section 4.4; in MPM e.g. Coombs et al.
// 2018, "Overcoming volumetric locking in material point methods").
//
//   indicator = sqrt(mean_i (p_i - pbar_i)^2) / |mean_i p_i|
//
// p_i the pressure of particle i, pbar_i the mean pressure of the other particles within one cell
// (distance <= dx) of it. A smooth field gives a value near zero (a linear field exactly zero away
// from the boundary); a field that alternates sign from particle to particle gives a value of order
// |amplitude| / |mean|, i.e. far above one.
#pragma once

#include <array>
#include <vector>

namespace firn::study {

struct PressureField {
  std::vector<std::array<double, 3>> positions;
  std::vector<double> pressures;  // Pa, one per position
};

struct CheckerboardMeasure {
  double indicator = 0;      // as above; 0 when there are fewer than two particles
  double mean_pressure = 0;  // Pa
};

CheckerboardMeasure pressure_checkerboard(const PressureField& field, double dx);

}  // namespace firn::study
