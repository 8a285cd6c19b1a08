#pragma once
// How far a channel may be edited. The slider spans the table's practical range
// (FapInfo::sliderMin..sliderMax); the spin box beside it and the presets reach further,
// because real animations exceed those hints (a sob nods the head by about 2 degrees, 3,500 AU,
// beyond the table's +/-1,860). Limits:
//   FAP 1, 2: the codes, 0..14 and 0..6;   tears: 0..kMaxTearParticles whole particles;
//   unidirectional with a range from 0: 0..10 x sliderMax;   others: +/-10 x max(|min|, |max|).
#include <lacrima/common/FapTable.h>

#include <algorithm>
#include <cstdlib>
#include <utility>

namespace lacrima::editing {

struct ChannelLimits {
  int min, max;
};

inline ChannelLimits editLimits(int fap) {
  const FapInfo& info = fapInfo(fap);
  if (isHighLevelFap(fap)) return {info.sliderMin, info.sliderMax};
  if (isTearChannel(fap)) return {0, kMaxTearParticles};
  const int reach = 10 * std::max(std::abs(info.sliderMin), std::abs(info.sliderMax));
  if (info.sliderMin >= 0) return {0, 10 * info.sliderMax};
  return {-reach, reach};
}

}  // namespace lacrima::editing
