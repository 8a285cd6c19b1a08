#include <lacrima/common/FapTable.h>
#include <lacrima/common/mood/BlinkModel.h>

#include <algorithm>

namespace lacrima::inline common {

void BlinkModel::advance(double seconds, double dt, double tearful, double crying) {
  fatigue_ = approach(fatigue_, crying, dt, kFatigueTime);
  const double rate = kRestRate + (kTearfulRate - kRestRate) * tearful;
  if (!started_) {
    started_ = true;
    next_ = seconds + 60 / rate * random_.uniform(0.3, 1.7);
  }
  if (seconds >= next_) {
    start_ = next_;
    hold_ = kHold + kTiredHold * fatigue_;
    next_ = start_ + kClose + hold_ + kOpen + 60 / rate * random_.uniform(0.3, 1.7);
    if (seconds >= next_) next_ = seconds + 60 / rate * random_.uniform(0.3, 1.7);  // long step
    ++blinks_;
  }
  const double in = seconds - start_;
  if (start_ < 0 || in < 0 || in >= kClose + hold_ + kOpen)
    closure_ = 0;
  else if (in < kClose)
    closure_ = smoothstep(in / kClose);
  else if (in < kClose + hold_)
    closure_ = 1;
  else
    closure_ = 1 - smoothstep((in - kClose - hold_) / kOpen);
}

void BlinkModel::apply(FapValues& face) const {
  for (int fap : {19, 20}) {
    float& lid = face[channelIndex(fap)];
    lid += static_cast<float>(kHeavyLids * fatigue_);
    lid += static_cast<float>(closure_ * std::max(0.0, kShut - lid));
  }
}

}  // namespace lacrima::inline common
