#pragma once
// Blinks and the heaviness crying leaves in the upper lids (docs/mood.md#blinks-and-gaze).
//
// Blinks come kRestRate a minute on a dry face (Bentivoglio et al. 1997, at rest) and up to
// kTearfulRate while tears flow (judged: tears and irritation call for blinks); each interval
// is the mean times a draw in [0.3, 1.7]. A blink closes the upper lids in kClose, holds them
// shut kHold (longer, up to kHold + kTiredHold, as crying goes on) and opens them in kOpen
// (Stern, Walrath and Goldstein 1984: about 100 ms to close, at most 300 ms shut, about 100 ms
// to reopen). The lids grow heavier with crying: a fatigue that follows the crying stage with a
// time constant of kFatigueTime lowers them by up to kHeavyLids.
#include <lacrima/common/FapChannels.h>
#include <lacrima/common/mood/MoodRandom.h>

#include <cstdint>

namespace lacrima::inline common {

class BlinkModel {
 public:
  static constexpr double kRestRate = 17;     // blinks/min
  static constexpr double kTearfulRate = 26;  // blinks/min, judged
  static constexpr double kClose = 0.1, kHold = 0.05, kTiredHold = 0.15, kOpen = 0.15;  // s
  static constexpr double kFatigueTime = 45;                                            // s, judged
  static constexpr double kHeavyLids = 180;  // IRISD units
  static constexpr double kShut = 1000;      // upper lid value of a closed eye (IRISD units)

  explicit BlinkModel(std::uint64_t seed) : random_(seed) {}

  // `tearful` and `crying` in [0, 1]: tears present now, the crying stage.
  void advance(double seconds, double dt, double tearful, double crying);
  void apply(FapValues& face) const;

  int blinks() const { return blinks_; }
  double closure() const { return closure_; }  // 0 open .. 1 shut

 private:
  MoodRandom random_;
  bool started_ = false;
  double next_ = 0;  // start of the next blink
  double start_ = -1, hold_ = kHold;
  int blinks_ = 0;
  double closure_ = 0;
  double fatigue_ = 0;
};

}  // namespace lacrima::inline common
