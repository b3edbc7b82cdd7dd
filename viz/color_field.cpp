#include "viz/color_field.hpp"

#include <stdexcept>

namespace firn::viz {

std::string color_field_title(const std::string& field) {
  if (field == "speed") return "speed (m/s)";
  if (field == "J") return "J (volume ratio)";
  if (field == "plastic_strain") return "plastic strain";
  if (field == "stress") return "von Mises stress (Pa)";
  throw std::invalid_argument("unknown colour field '" + field + "'");
}

}  // namespace firn::viz
