#pragma once
// Tears (docs/mood.md#tears): how many tear particles each eye's source holds (channels 69 and
// 70, absolute counts: a rise spawns particles, a fall removes the oldest).
//
// The moods drive tears as the thesis's Table 2.1 says (sadness and anger) and as Borgquist's
// third mood of crying does (joy, "laughter to the point of tears"):
//   drive = min(1, sadness + 0.7 smoothstep((anger - 0.5) / 0.5) + 0.5 smoothstep((joy - 0.6) /
//   0.4))
// While the drive stays above kThreshold a clock runs (and runs back twice as fast below it,
// so a short dip does not restart the crying). The eyes well when the clock passes the onset
// latency L (sadness kSadOnset, anger kAngryOnset, joy kJoyOnset, mixed by each one's share of
// the drive) and spill kSpillAfter seconds later. The count's target is
//   kWelling w + kSpilling s drive           (w, s the welling and spilling stages, 0..1)
// it grows toward the target at most kGrowth (1 + 3 drive) particles a second and falls back
// with a time constant of kTaper. One eye, drawn per take, makes a little less (0.85 to 1).
#include <lacrima/common/mood/MoodRandom.h>
#include <lacrima/common/mood/Moods.h>

#include <array>
#include <cstdint>

namespace lacrima::inline common {

class TearProduction {
 public:
  static constexpr double kThreshold = 0.2;
  static constexpr double kSadOnset = 3, kAngryOnset = 5, kJoyOnset = 6;  // s, judged
  static constexpr double kSpillAfter = 5;                                // s, judged
  static constexpr double kWelling = 20, kSpilling = 100;                 // particles
  static constexpr double kGrowth = 6;                                    // particles/s
  static constexpr double kTaper = 3;                                     // s

  explicit TearProduction(std::uint64_t seed);

  static double drive(const MoodLevels& levels);

  void advance(double dt, const MoodLevels& levels);

  // Whole particles at the left and right eye.
  std::array<int, 2> counts() const { return rounded_; }
  double welling() const { return welling_; }
  double spilling() const { return spilling_; }
  // How far into crying the face is, 0..1: what deepens the expression and tires the lids.
  double crying() const { return 0.35 * welling_ + 0.65 * spilling_; }
  // Tears present now, 0..1 (100 particles an eye count as full).
  double tearful() const;

 private:
  std::array<double, 2> share_{1, 1};
  double clock_ = 0;
  double onset_ = kSadOnset;
  double welling_ = 0, spilling_ = 0;
  std::array<double, 2> count_{};
  std::array<int, 2> rounded_{};
};

}  // namespace lacrima::inline common
