#include <lacrima/common/FapAnimation.h>

#include "FapInterpolation.h"

#include <array>
#include <cmath>

namespace lacrima::inline common {

ChannelMask FapAnimation::usedChannels() const {
  // Row by row into bytes rather than bit by bit: the compiler vectorises this scan.
  std::array<unsigned char, kChannelCount> nonZero{};
  for (const FapValues& frame : frames)
    for (int c = 0; c < kChannelCount; ++c) nonZero[c] |= static_cast<unsigned char>(frame[c] != 0);
  ChannelMask used = animated;
  for (int c = 0; c < kChannelCount; ++c)
    if (nonZero[c]) used.set(c);
  return used;
}

bool FapAnimation::hasTears() const {
  for (const FapValues& frame : frames)
    if (frame[channelIndex(kTearLeftFap)] != 0 || frame[channelIndex(kTearRightFap)] != 0)
      return true;
  return false;
}

FapValues FapAnimation::sample(double seconds) const {
  if (frames.empty()) return FapValues{};
  const double position = seconds * fps;
  // Written so that NaN (bad time or fps) lands on the first frame rather than indexing with it.
  if (!(position > 0)) return frames.front();
  const double last = static_cast<double>(frames.size() - 1);
  if (position >= last) return frames.back();
  const double whole = std::floor(position);
  const auto i = static_cast<std::size_t>(whole);
  FapValues out;
  detail::blendFrames(frames[i], frames[i + 1], position - whole, out);
  return out;
}

}  // namespace lacrima::inline common
