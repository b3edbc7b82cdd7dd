// Writes rendered frames off the simulation thread: one worker encodes frames/NNNNN.png and
// pipes the same frame to ffmpeg, in order. The queue holds a few frames; push() waits when it
// is full, so memory stays bounded when encoding is slower than rendering.
#pragma once

#include <condition_variable>
#include <deque>
#include <exception>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "viz/ffmpeg_pipe.hpp"
#include "engine/output/image.hpp"

namespace firn::viz {

class FrameWriter {
 public:
  // `png_dir`: where NNNNN.png go ("" for none); `video`: null for none.
  FrameWriter(std::string png_dir, std::unique_ptr<FfmpegPipe> video, std::size_t capacity = 3);
  ~FrameWriter();  // stops the worker; an unfinished video is abandoned
  FrameWriter(const FrameWriter&) = delete;
  FrameWriter& operator=(const FrameWriter&) = delete;

  // Queues a frame; rethrows the worker's first error.
  void push(int frame, Image image);
  // Writes what is queued, closes the video; rethrows the worker's first error.
  void finish();

 private:
  void work();
  void rethrow();

  std::string png_dir_;
  std::unique_ptr<FfmpegPipe> video_;
  std::size_t capacity_;
  std::deque<std::pair<int, Image>> queue_;
  std::mutex mutex_;
  std::condition_variable changed_;
  bool closing_ = false;
  std::exception_ptr error_;
  std::thread worker_;
};

}  // namespace firn::viz
