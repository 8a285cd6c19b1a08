#include <lacrima/editing/KeyReduction.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace lacrima::editing {
namespace {

ChannelMask channelsOf(const FapAnimation& animation) {
  return animation.animated.any() ? animation.animated : animation.usedChannels();
}

std::vector<int> indicesOf(const ChannelMask& mask) {
  std::vector<int> out;
  for (int i = 0; i < kChannelCount; ++i)
    if (mask.test(i)) out.push_back(i);
  return out;
}

// e(i) for the span (a, b), computed with the same arithmetic as linear key playback
// (Keyframes.cpp: value a + s * (b - a) with s from the key times, stored as float).
double frameError(const FapAnimation& animation, const std::vector<int>& channels, int a, int b,
                  int i) {
  const double ta = a / animation.fps;
  const double tb = b / animation.fps;
  const double t = i / animation.fps;
  const double s = (t - ta) / (tb - ta);
  const FapValues& fa = animation.frames[a];
  const FapValues& fb = animation.frames[b];
  const FapValues& fi = animation.frames[i];
  double worst = 0.0;
  for (int c : channels) {
    const int fap = fapNumber(c);
    double r;
    if (isHighLevelFap(fap)) {
      r = fa[c];
    } else {
      r = static_cast<float>(fa[c] + s * (static_cast<double>(fb[c]) - fa[c]));
      if (isTearChannel(fap)) r = std::max(0.0, std::round(r));
    }
    worst = std::max(worst, std::abs(r - fi[c]));
  }
  return worst;
}

}  // namespace

std::vector<int> reduceKeyFrames(const FapAnimation& animation, double tolerance) {
  if (!(tolerance >= 0.0) || !std::isfinite(tolerance))
    throw std::invalid_argument("key reduction: tolerance must be a finite number >= 0");
  const int n = animation.frameCount();
  if (n <= 2) {
    std::vector<int> all(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) all[static_cast<std::size_t>(i)] = i;
    return all;
  }
  const std::vector<int> channels = indicesOf(channelsOf(animation));
  std::vector<char> keep(static_cast<std::size_t>(n), 0);
  keep.front() = keep.back() = 1;
  // An explicit stack: a 13,200-frame file split at one end every time must not recurse
  // 13,200 deep.
  std::vector<std::pair<int, int>> spans{{0, n - 1}};
  while (!spans.empty()) {
    const auto [a, b] = spans.back();
    spans.pop_back();
    if (b - a < 2) continue;
    int worstFrame = -1;
    double worst = tolerance;
    for (int i = a + 1; i < b; ++i) {
      const double e = frameError(animation, channels, a, b, i);
      if (e > worst) {
        worst = e;
        worstFrame = i;
      }
    }
    if (worstFrame < 0) continue;
    keep[static_cast<std::size_t>(worstFrame)] = 1;
    spans.emplace_back(a, worstFrame);
    spans.emplace_back(worstFrame, b);
  }
  std::vector<int> kept;
  for (int i = 0; i < n; ++i)
    if (keep[static_cast<std::size_t>(i)]) kept.push_back(i);
  return kept;
}

double reductionError(const FapAnimation& animation, const std::vector<int>& kept) {
  const std::vector<int> channels = indicesOf(channelsOf(animation));
  double worst = 0.0;
  for (std::size_t k = 0; k + 1 < kept.size(); ++k)
    for (int i = kept[k] + 1; i < kept[k + 1]; ++i)
      worst = std::max(worst, frameError(animation, channels, kept[k], kept[k + 1], i));
  return worst;
}

}  // namespace lacrima::editing
