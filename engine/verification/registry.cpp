#include <stdexcept>

#include "engine/verification/verification.hpp"

namespace firn {

namespace {
const char* const kDriverPrefix = "material_driver_";
const char* const kDriverModels[] = {"hyperelastic_plastic", "snow_stomakhin", "mooney_rivlin", "snow_cam_clay"};
}  // namespace

std::vector<std::string> verification_problems() {
  std::vector<std::string> names = {"vibrating_bar", "manufactured_solution", "two_spheres", "incline_sliding",
                                    "incline_rolling"};
  for (const char* model : kDriverModels) names.push_back(kDriverPrefix + std::string(model));
  return names;
}

std::vector<std::string> verification_problems_on_request() { return {"incline_rolling_fine"}; }

std::vector<VerificationRow> run_verification(const std::string& problem, const VerificationOptions& options) {
  if (problem == "vibrating_bar") return verify_vibrating_bar(options);
  if (problem == "manufactured_solution") return verify_manufactured_solution(options);
  if (problem == "two_spheres") return verify_two_spheres(options);
  if (problem == "incline_sliding") return verify_incline_sliding(options);
  if (problem == "incline_rolling") return verify_incline_rolling(options);
  if (problem == "incline_rolling_fine") return verify_incline_rolling_fine(options);
  for (const char* model : kDriverModels)
    if (problem == kDriverPrefix + std::string(model)) return verify_material_driver(model);
  throw std::invalid_argument("unknown verification problem '" + problem + "'");
}

}  // namespace firn
