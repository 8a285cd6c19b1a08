#pragma once
// Records what a live player receives, after retargeting, as a FAP file: frame k holds the
// newest frame that arrived before start + (k + 1/2) / fps, so a stream sent at the recording's
// rate is recorded frame for frame despite a jitter of up to half a frame, and a faster one is
// sampled. The rate is the one named (--record-rate), else the one the stream names (a FAP
// header, Live Link's frame rate), else kDefaultRate. The channels masked are those any frame
// set. Memory: one frame per recorded frame, at most kMaxFrames (13 hours at 22 fps); beyond,
// recording stops and says so. stop() writes the file atomically (FapWriter::save).
#include <lacrima/common/FapAnimation.h>
#include <lacrima/live/LiveInput.h>

#include <optional>
#include <string>

namespace lacrima::live {

class LiveRecorder {
 public:
  static constexpr double kDefaultRate = 30;
  static constexpr int kMaxFrames = 1 << 20;

  // `rate`: the rate named by the user, or nullopt to take the stream's.
  LiveRecorder(std::string path, std::optional<double> rate);

  void add(const LiveFrame& frame);
  // Frames so far (0 before the first arrives).
  int frameCount() const;
  bool full() const { return full_; }
  double rate() const { return animation_.fps; }
  const FapAnimation& animation() const { return animation_; }
  const std::string& path() const { return path_; }
  // Writes the file (FapWriter::save, atomic); throws FileError. An empty recording writes
  // nothing and returns false.
  bool stop();

 private:
  std::string path_;
  std::optional<double> namedRate_;
  FapAnimation animation_;
  double start_ = -1;
  FapValues newest_{};
  bool full_ = false;
};

}  // namespace lacrima::live
