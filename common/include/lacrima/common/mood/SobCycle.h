#pragma once
// Sobbing (docs/mood.md#sobbing): convulsive breathing cycles, each a sharp inhale (jaw drops,
// head tips back, inner brows jump, lip corners lift) and a shuddering exhale in one to three
// jerks (head drops, eyes squeeze, lip corners pull down), after the preset's 1.6 s sob.
//
// Depth d = smoothstep((sadness - 0.3) / 0.6), or half of smoothstep((anger - 0.6) / 0.4) when
// that is larger (angry crying gasps less); none for joy, nor for anger below 0.6. Rate
// kRestRate + (kFullRate - kRestRate) d cycles a minute; each cycle's period is that rate's
// period times a draw in [0.8, 1.25], its depth times a draw in [0.75, 1.15], its inhale
// kInhaleShare of the period. A cycle begins where the last one ended, so the cycles fall at
// the same times at any frame rate.
#include <lacrima/common/FapChannels.h>
#include <lacrima/common/mood/MoodRandom.h>

#include <cstdint>

namespace lacrima::inline common {

class SobCycle {
 public:
  static constexpr double kRestRate = 18;  // cycles/min at the lowest depth
  static constexpr double kFullRate = 42;  // cycles/min at full depth
  static constexpr double kInhaleShare = 0.27;

  explicit SobCycle(std::uint64_t seed) : random_(seed) {}

  static double depth(double sadness, double anger);

  // Moves to `seconds` (not before the last call).
  void advance(double seconds, double sadness, double anger);
  // Adds this moment of the cycle to `face`.
  void apply(FapValues& face) const;

  int cyclesStarted() const { return cycles_; }
  double inhale() const { return inhale_; }  // 0..1 this moment (tests, docs)

 private:
  MoodRandom random_;
  bool active_ = false;
  bool idle_ = true;  // no cycle ran at the last call
  double start_ = 0, period_ = 0, amplitude_ = 0;
  int jerks_ = 1;
  int cycles_ = 0;
  double inhale_ = 0, shudder_ = 0;  // the two shapes at the current moment, times amplitude
};

}  // namespace lacrima::inline common
