// Output files appear complete or not at all (DESIGN.md section 5): each is written to
// "NAME.tmp" and renamed over NAME once closed, so a crash or an interrupt never leaves a
// half-written file under its real name.
#pragma once

#include <fstream>
#include <string>

namespace firn {

class AtomicFile {
 public:
  explicit AtomicFile(std::string path);
  ~AtomicFile();  // removes the temporary if commit() was never reached
  std::ofstream& stream() { return out_; }
  void commit();  // flushes, closes and renames; throws std::runtime_error on an I/O failure

 private:
  std::string path_, tmp_;
  std::ofstream out_;
  bool committed_ = false;
};

void write_file_atomically(const std::string& path, const std::string& content);

// Creates the folder and any missing parents (mkdir -p); throws std::runtime_error on failure.
void make_directories(const std::string& path);

}  // namespace firn
