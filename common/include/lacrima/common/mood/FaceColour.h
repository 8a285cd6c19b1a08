#pragma once
// Redness and blush over time (docs/mood.md#face-colours). Table 2.1 of the 2009 thesis: red
// eyes come after tears, blushing with shame and anger.
//
// Irritation I builds with the tears present, dI/dt = kBuild tearful - I / kFade (fading over
// minutes, judged), and the redness is I / (kHalf + I): it saturates and never passes 1. The
// blush follows min(1, 0.9 shame + 0.55 anger), rising with a time constant of kBlushRise and
// falling with kBlushFall (judged).
#include <lacrima/common/FaceColours.h>
#include <lacrima/common/mood/Moods.h>

namespace lacrima::inline common {

class FaceColour {
 public:
  static constexpr double kBuild = 0.05;                      // irritation per second of full tears
  static constexpr double kFade = 300;                        // s
  static constexpr double kHalf = 0.6;                        // irritation at half redness
  static constexpr double kBlushRise = 1.5, kBlushFall = 10;  // s

  void advance(double dt, double tearful, const MoodLevels& levels);
  FaceColours colours() const { return {irritation_ / (kHalf + irritation_), blush_}; }

 private:
  double irritation_ = 0;
  double blush_ = 0;
};

}  // namespace lacrima::inline common
