#include "viz/ffmpeg_pipe.hpp"

#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace firn::viz {

std::string find_on_path(const std::string& program) {
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "/usr/bin:/bin");
  for (std::string dir; std::getline(dirs, dir, ':');) {
    const std::string candidate = (dir.empty() ? "." : dir) + "/" + program;
    struct stat st;
    if (::stat(candidate.c_str(), &st) == 0 && S_ISREG(st.st_mode) && ::access(candidate.c_str(), X_OK) == 0)
      return candidate;
  }
  return "";
}

FfmpegPipe::FfmpegPipe(const std::string& path, int width, int height, int fps)
    : path_(path), tmp_(path + ".tmp"), width_(width), height_(height) {
  const std::string ffmpeg = find_on_path("ffmpeg");
  if (ffmpeg.empty()) throw std::runtime_error("--video needs ffmpeg, which is not on PATH (install ffmpeg)");
  if (width % 2 || height % 2)
    throw std::runtime_error("--video needs an even width and height for yuv420p (got " + std::to_string(width) + "x" +
                             std::to_string(height) + ")");
  const std::string size = std::to_string(width) + "x" + std::to_string(height), rate = std::to_string(fps);
  const std::vector<std::string> args = {ffmpeg, "-hide_banner", "-loglevel", "error", "-nostdin", "-y",
                                         "-f", "rawvideo", "-pix_fmt", "rgb24", "-s", size, "-r", rate, "-i", "-",
                                         "-c:v", "libx264", "-pix_fmt", "yuv420p", "-f", "mp4", tmp_};
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  int fds[2];
  if (::pipe(fds) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
  ::signal(SIGPIPE, SIG_IGN);  // a dead ffmpeg shows as EPIPE from write(), not a killed firn
  child_ = ::fork();
  if (child_ < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
  }
  if (child_ == 0) {
    ::setpriority(PRIO_PROCESS, 0, 19);  // below the simulation, like the PNG writer
    ::setpgid(0, 0);  // its own process group: Ctrl-C stops firn, which then closes the video
    ::dup2(fds[0], STDIN_FILENO);
    ::close(fds[0]);
    ::close(fds[1]);
    ::execvp(argv[0], argv.data());
    ::_exit(127);
  }
  ::close(fds[0]);
  fd_ = fds[1];
}

FfmpegPipe::~FfmpegPipe() {
  if (child_ <= 0) return;
  ::close(fd_);
  ::kill(child_, SIGKILL);
  ::waitpid(child_, nullptr, 0);
  std::remove(tmp_.c_str());
}

void FfmpegPipe::write(const Image& frame) {
  if (frame.width != width_ || frame.height != height_) throw std::logic_error("video frame of the wrong size");
  const std::uint8_t* p = frame.rgb.data();
  std::size_t left = frame.rgb.size();
  while (left > 0) {
    const ssize_t n = ::write(fd_, p, left);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw std::runtime_error(std::string("ffmpeg stopped reading frames: ") + std::strerror(errno));
    p += n;
    left -= std::size_t(n);
  }
}

void FfmpegPipe::finish() {
  ::close(fd_);
  int status = 0;
  while (::waitpid(child_, &status, 0) < 0 && errno == EINTR) {
  }
  child_ = -1;
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::remove(tmp_.c_str());
    throw std::runtime_error("ffmpeg failed (exit status " +
                             std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) + ")");
  }
  if (std::rename(tmp_.c_str(), path_.c_str()) != 0)
    throw std::runtime_error("cannot rename " + tmp_ + ": " + std::strerror(errno));
}

}  // namespace firn::viz
