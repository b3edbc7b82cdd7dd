// Physical quantities and unit conversion for scene values (DESIGN.md section 5): a number is SI;
// a string "VALUE UNIT" ("70 mm", "0.4 g/cm^3", "0.078 MPa", "10 mph", "0.5 ms", "30 deg") is
// converted to SI after checking that the unit measures the expected quantity.
#pragma once

#include <string>

namespace firn {

enum class Quantity {
  dimensionless,
  length,
  time,
  mass,
  density,
  pressure,  // also stress and moduli
  velocity,
  acceleration,
  force,
  angle,             // SI: radians
  angular_velocity,  // SI: rad/s
  moment_of_inertia,  // SI: kg m^2
  rate,               // SI: 1/s
};

// The SI unit written after a value of this quantity, e.g. "Pa" ("" for dimensionless).
const char* si_unit(Quantity q);
const char* quantity_name(Quantity q);

// Converts "VALUE UNIT" (or a bare number) to SI. Throws std::invalid_argument with a message that
// names the problem (not a finite number, an unknown unit, or a unit of another quantity).
double parse_quantity(const std::string& text, Quantity q);

}  // namespace firn
