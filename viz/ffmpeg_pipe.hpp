// Video through ffmpeg (DESIGN.md section 7): raw RGB frames piped to
//   ffmpeg -f rawvideo -pix_fmt rgb24 -s WxH -r FPS -i - -c:v libx264 -pix_fmt yuv420p OUT
// started with fork and execvp on an argument vector, never through a shell. The video is
// written under a temporary name and renamed when ffmpeg has finished successfully.
#pragma once

#include <sys/types.h>

#include <string>

#include "engine/output/image.hpp"

namespace firn::viz {

// The full path of `program` found on PATH, or "" when it is not there.
std::string find_on_path(const std::string& program);

class FfmpegPipe {
 public:
  // Throws std::runtime_error if ffmpeg is not on PATH or the size is odd (yuv420p needs even).
  FfmpegPipe(const std::string& path, int width, int height, int fps);
  ~FfmpegPipe();  // abandons an unfinished video: kills ffmpeg and removes the temporary
  FfmpegPipe(const FfmpegPipe&) = delete;
  FfmpegPipe& operator=(const FfmpegPipe&) = delete;

  void write(const Image& frame);
  // Closes the pipe, waits for ffmpeg and renames the video into place; throws if ffmpeg failed.
  void finish();

 private:
  std::string path_, tmp_;
  int width_, height_;
  int fd_ = -1;
  pid_t child_ = -1;
};

}  // namespace firn::viz
