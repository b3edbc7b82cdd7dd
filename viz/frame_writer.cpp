#include "viz/frame_writer.hpp"

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <cstdio>

#include "engine/output/png_file.hpp"

namespace firn::viz {

FrameWriter::FrameWriter(std::string png_dir, std::unique_ptr<FfmpegPipe> video, std::size_t capacity)
    : png_dir_(std::move(png_dir)), video_(std::move(video)), capacity_(capacity), worker_([this] { work(); }) {}

FrameWriter::~FrameWriter() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    closing_ = true;
  }
  changed_.notify_all();
  worker_.join();
}

void FrameWriter::rethrow() {
  if (error_) std::rethrow_exception(error_);
}

void FrameWriter::push(int frame, Image image) {
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [&] { return queue_.size() < capacity_ || error_; });
  rethrow();
  queue_.emplace_back(frame, std::move(image));
  changed_.notify_all();
}

void FrameWriter::finish() {
  {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [&] { return queue_.empty() || error_; });
    rethrow();
  }
  if (video_) video_->finish();
}

void FrameWriter::work() {
  // Below the simulation's threads: OpenMP's barriers stall whenever a worker is preempted, so
  // the encoder takes the cores the simulation leaves idle (and the bounded queue makes the
  // simulation wait for it when it falls behind).
  ::setpriority(PRIO_PROCESS, pid_t(::syscall(SYS_gettid)), 19);
  for (;;) {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [&] { return !queue_.empty() || closing_; });
    if (queue_.empty()) return;
    auto& [frame, image] = queue_.front();
    lock.unlock();
    try {
      if (!png_dir_.empty()) {
        char name[32];
        std::snprintf(name, sizeof name, "/%05d.png", frame);
        write_png(png_dir_ + name, image);
      }
      if (video_) video_->write(image);
    } catch (...) {
      lock.lock();
      error_ = std::current_exception();
      queue_.clear();
      changed_.notify_all();
      return;
    }
    lock.lock();
    queue_.pop_front();
    changed_.notify_all();
  }
}

}  // namespace firn::viz
