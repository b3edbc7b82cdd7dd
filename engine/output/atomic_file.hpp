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
  // Flushes, closes and renames; throws std::runtime_error on an I/O failure. `durable` also
  // forces the file and then its folder's entry to disk (fsync), so that it survives a power cut
  // or a reboot: for checkpoints, whose loss costs a run.
  void commit(bool durable = false);

 private:
  std::string path_, tmp_;
  std::ofstream out_;
  bool committed_ = false;
};

void write_file_atomically(const std::string& path, const std::string& content, bool durable = false);

// The whole content of a file; throws std::runtime_error if it cannot be read.
std::string read_text_file(const std::string& path);

// Creates the folder and any missing parents (mkdir -p); throws std::runtime_error on failure.
void make_directories(const std::string& path);

}  // namespace firn
