#include "engine/scene/units.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace firn {
namespace {

struct Unit {
  const char* symbol;
  Quantity quantity;
  double to_si;
};

constexpr double kPi = 3.14159265358979323846;

// Symbols as users type them; one entry per spelling. Factors are exact definitions (NIST SP 811).
constexpr Unit kUnits[] = {
    {"m", Quantity::length, 1},
    {"cm", Quantity::length, 1e-2},
    {"mm", Quantity::length, 1e-3},
    {"um", Quantity::length, 1e-6},
    {"km", Quantity::length, 1e3},
    {"in", Quantity::length, 0.0254},
    {"ft", Quantity::length, 0.3048},
    {"s", Quantity::time, 1},
    {"ms", Quantity::time, 1e-3},
    {"us", Quantity::time, 1e-6},
    {"min", Quantity::time, 60},
    {"h", Quantity::time, 3600},
    {"kg", Quantity::mass, 1},
    {"g", Quantity::mass, 1e-3},
    {"mg", Quantity::mass, 1e-6},
    {"kg/m^3", Quantity::density, 1},
    {"kg/m3", Quantity::density, 1},
    {"g/cm^3", Quantity::density, 1e3},
    {"g/cm3", Quantity::density, 1e3},
    {"Pa", Quantity::pressure, 1},
    {"kPa", Quantity::pressure, 1e3},
    {"MPa", Quantity::pressure, 1e6},
    {"GPa", Quantity::pressure, 1e9},
    {"bar", Quantity::pressure, 1e5},
    {"psi", Quantity::pressure, 6894.757293168361},
    {"m/s", Quantity::velocity, 1},
    {"cm/s", Quantity::velocity, 1e-2},
    {"mm/s", Quantity::velocity, 1e-3},
    {"km/h", Quantity::velocity, 1 / 3.6},
    {"mph", Quantity::velocity, 0.44704},
    {"ft/s", Quantity::velocity, 0.3048},
    {"m/s^2", Quantity::acceleration, 1},
    {"mm/s^2", Quantity::acceleration, 1e-3},
    {"N", Quantity::force, 1},
    {"mN", Quantity::force, 1e-3},
    {"kN", Quantity::force, 1e3},
    {"lbf", Quantity::force, 4.4482216152605},
    {"rad", Quantity::angle, 1},
    {"deg", Quantity::angle, kPi / 180},
    {"rad/s", Quantity::angular_velocity, 1},
    {"deg/s", Quantity::angular_velocity, kPi / 180},
    {"rpm", Quantity::angular_velocity, 2 * kPi / 60},
    {"kg m^2", Quantity::moment_of_inertia, 1},
    {"kg m2", Quantity::moment_of_inertia, 1},
    {"g cm^2", Quantity::moment_of_inertia, 1e-7},
    {"1/s", Quantity::rate, 1},
    {"1/ms", Quantity::rate, 1e3},
};

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t");
  return s.substr(b, e - b + 1);
}

}  // namespace

const char* si_unit(Quantity q) {
  for (const Unit& u : kUnits)
    if (u.quantity == q && u.to_si == 1) return u.symbol;
  return "";
}

const char* quantity_name(Quantity q) {
  switch (q) {
    case Quantity::dimensionless: return "dimensionless number";
    case Quantity::length: return "length";
    case Quantity::time: return "time";
    case Quantity::mass: return "mass";
    case Quantity::density: return "density";
    case Quantity::pressure: return "pressure";
    case Quantity::velocity: return "velocity";
    case Quantity::acceleration: return "acceleration";
    case Quantity::force: return "force";
    case Quantity::angle: return "angle";
    case Quantity::angular_velocity: return "angular velocity";
    case Quantity::moment_of_inertia: return "moment of inertia";
    case Quantity::rate: return "rate";
  }
  return "";
}

double parse_quantity(const std::string& text, Quantity q) {
  const std::string t = trim(text);
  const char* begin = t.c_str();
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(begin, &end);
  if (end == begin || errno == ERANGE)
    throw std::invalid_argument("'" + text + "' is not a number with a unit");
  if (!std::isfinite(value)) throw std::invalid_argument("'" + text + "' is not a finite number");
  const std::string unit = trim(std::string(end));
  if (unit.empty()) return value;
  for (const Unit& u : kUnits) {
    if (unit != u.symbol) continue;
    if (u.quantity != q)
      throw std::invalid_argument("unit '" + unit + "' measures " + quantity_name(u.quantity) + ", expected " +
                                  quantity_name(q) + (q == Quantity::dimensionless ? "" : std::string(" (") + si_unit(q) + ")"));
    return value * u.to_si;
  }
  throw std::invalid_argument("unknown unit '" + unit + "' for " + quantity_name(q) +
                              (q == Quantity::dimensionless ? "" : std::string(" (SI: ") + si_unit(q) + ")"));
}

}  // namespace firn
