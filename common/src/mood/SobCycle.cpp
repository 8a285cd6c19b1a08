#include <lacrima/common/FapTable.h>
#include <lacrima/common/mood/SobCycle.h>

#include <algorithm>
#include <cmath>

namespace lacrima::inline common {

double SobCycle::depth(double sadness, double anger) {
  const double sad = smoothstep((sadness - 0.3) / 0.6);
  const double angry = 0.5 * smoothstep((anger - 0.6) / 0.4);
  return std::max(sad, angry);
}

void SobCycle::advance(double seconds, double sadness, double anger) {
  const double d = depth(sadness, anger);
  if (active_ && seconds >= start_ + period_) {
    start_ += period_;  // the next cycle follows on without a gap
    active_ = false;
  }
  if (!active_) {
    if (d <= 0) {
      inhale_ = shudder_ = 0;
      idle_ = true;
      return;
    }
    if (idle_) start_ = seconds;  // after a pause the next sob begins now
    idle_ = false;
    const double rate = kRestRate + (kFullRate - kRestRate) * d;
    period_ = 60 / rate * random_.uniform(0.8, 1.25);
    amplitude_ = d * random_.uniform(0.75, 1.15);
    jerks_ = 1 + static_cast<int>(random_.uniform() * 3);
    if (seconds >= start_ + period_) start_ = seconds;  // a frame longer than a cycle
    active_ = true;
    ++cycles_;
  }
  const double p = std::clamp((seconds - start_) / period_, 0.0, 1.0);
  if (p < kInhaleShare) {
    inhale_ = amplitude_ * smoothstep(p / kInhaleShare);
    shudder_ = 0;
  } else {
    const double q = (p - kInhaleShare) / (1 - kInhaleShare);
    const double steps = q * jerks_;
    const double done = std::floor(steps);
    // each jerk lets a share of the breath out quickly, then holds: convulsive, not smooth
    const double out = std::min(1.0, (done + smoothstep((steps - done) * 2.5)) / jerks_);
    inhale_ = amplitude_ * (1 - out);
    shudder_ = amplitude_ * 4 * q * (1 - q);
  }
}

void SobCycle::apply(FapValues& face) const {
  if (inhale_ == 0 && shudder_ == 0) return;
  const auto add = [&](int fap, double perInhale, double perShudder) {
    face[channelIndex(fap)] += static_cast<float>(perInhale * inhale_ + perShudder * shudder_);
  };
  add(3, 240, 60);                            // open_jaw
  add(48, -3400, 2800);                       // head_pitch: back on the inhale, down on the exhale
  for (int fap : {31, 32}) add(fap, 80, 20);  // inner brows
  for (int fap : {19, 20}) add(fap, -90, 190);  // upper lids: open, then squeeze
  for (int fap : {12, 13, 59, 60}) add(fap, 60, -50);
  add(18, -60, 40);  // depress_chin
  for (int fap : {6, 7}) add(fap, 0, 40);
}

}  // namespace lacrima::inline common
