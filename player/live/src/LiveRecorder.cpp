#include <lacrima/live/LiveRecorder.h>

#include <lacrima/common/FapWriter.h>

#include <cmath>

namespace lacrima::live {

LiveRecorder::LiveRecorder(std::string path, std::optional<double> rate)
    : path_(std::move(path)), namedRate_(rate) {
  animation_.name = "live";
  animation_.fps = rate.value_or(kDefaultRate);
}

void LiveRecorder::add(const LiveFrame& frame) {
  if (start_ < 0) {
    start_ = frame.arrival;
    if (!namedRate_ && frame.frameRate) animation_.fps = *frame.frameRate;
  }
  // Frame k holds the newest frame that arrived before start + (k + 1/2) / fps.
  const double slot = (frame.arrival - start_) * animation_.fps + 0.5;
  const long long index = std::isfinite(slot) && slot > 0 ? static_cast<long long>(slot) : 0;
  if (index >= kMaxFrames) {
    full_ = true;
    return;
  }
  auto& frames = animation_.frames;
  // Slots no frame arrived in hold the one before.
  while (!frames.empty() && static_cast<long long>(frames.size()) < index)
    frames.push_back(newest_);
  if (static_cast<long long>(frames.size()) <= index)
    frames.push_back(frame.values);
  else
    frames.back() = frame.values;  // the newest in its slot wins
  newest_ = frame.values;
  animation_.animated |= frame.mask;
}

int LiveRecorder::frameCount() const { return animation_.frameCount(); }

bool LiveRecorder::stop() {
  if (animation_.frames.empty()) return false;
  FapWriter::save(animation_, path_);
  return true;
}

}  // namespace lacrima::live
