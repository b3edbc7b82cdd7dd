// Optional per-launch timing shared by every backend: when a backend has a LaunchProfile, each
// named launch adds its wall time under its name. Costs one null check per launch otherwise.
#pragma once

#include <chrono>
#include <map>
#include <string>

namespace firn::backend {

struct LaunchProfile {
  struct Entry {
    double seconds = 0;
    long launches = 0;
  };
  std::map<std::string, Entry> entries;

  void add(const char* name, double seconds) {
    Entry& e = entries[name];
    e.seconds += seconds;
    ++e.launches;
  }
};

// Times one launch into `profile` (if any) for the lifetime of the object.
class ScopedLaunch {
 public:
  ScopedLaunch(LaunchProfile* profile, const char* name) : profile_(profile), name_(name) {
    if (profile_) start_ = std::chrono::steady_clock::now();
  }
  ~ScopedLaunch() {
    if (profile_)
      profile_->add(name_, std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count());
  }
  ScopedLaunch(const ScopedLaunch&) = delete;
  ScopedLaunch& operator=(const ScopedLaunch&) = delete;

 private:
  LaunchProfile* profile_;
  const char* name_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace firn::backend
