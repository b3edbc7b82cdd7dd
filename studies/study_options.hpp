// The options every `firn study` report takes (accuracy, stability).
#pragma once

#include <string>

namespace firn::study {

struct StudyOptions {
  bool quick = false;              // a representative subset that finishes in under 3 minutes on 2 cores
  std::string out;                 // the report's folder
  int threads = 0;                 // OpenMP threads per run (0: all cores)
  std::string backend = "openmp";  // by name (engine/backend_kind.hpp), available here
};

}  // namespace firn::study
