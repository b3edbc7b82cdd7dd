#include <stdexcept>

#include "engine/verification/verification.hpp"

namespace firn {

std::vector<std::string> verification_problems() { return {"vibrating_bar", "manufactured_solution", "two_spheres"}; }

std::vector<VerificationRow> run_verification(const std::string& problem, const VerificationOptions& options) {
  if (problem == "vibrating_bar") return verify_vibrating_bar(options);
  if (problem == "manufactured_solution") return verify_manufactured_solution(options);
  if (problem == "two_spheres") return verify_two_spheres(options);
  throw std::invalid_argument("unknown verification problem '" + problem + "'");
}

}  // namespace firn
