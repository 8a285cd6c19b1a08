#include <lacrima/common/mood/FaceColour.h>
#include <lacrima/common/mood/MoodRandom.h>

#include <algorithm>

namespace lacrima::inline common {

void FaceColour::advance(double dt, double tearful, const MoodLevels& levels) {
  // implicit Euler: stable at any step
  irritation_ = (irritation_ + dt * kBuild * tearful) / (1 + dt / kFade);
  const double target = std::min(1.0, 0.9 * levels[Mood::Shame] + 0.55 * levels[Mood::Anger]);
  blush_ = approach(blush_, target, dt, target > blush_ ? kBlushRise : kBlushFall);
}

}  // namespace lacrima::inline common
