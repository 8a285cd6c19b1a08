#pragma once
// How one frame blends into the next. Shared by FapAnimation::sample and the reader's gap
// filling so that both treat the special channels alike. Private to lacrima_common.
#include <lacrima/common/FapChannels.h>

#include <cmath>

namespace lacrima::inline common::detail {

// out = a + (b - a) * t per channel, t in [0, 1]. `out` may alias neither a nor b.
inline void blendFrames(const FapValues& a, const FapValues& b, double t, FapValues& out) {
  for (int c = 0; c < kChannelCount; ++c) {
    const int fap = fapNumber(c);
    if (isHighLevelFap(fap)) {
      out[c] = a[c];  // viseme and expression codes: blending two codes names a third, wrong one
      continue;
    }
    const double v = a[c] + (static_cast<double>(b[c]) - a[c]) * t;
    out[c] = static_cast<float>(isTearChannel(fap) ? std::round(v) : v);  // whole particles
  }
}

}  // namespace lacrima::inline common::detail
