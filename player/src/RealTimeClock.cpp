#include <lacrima/player/RealTimeClock.h>

namespace lacrima::player {

void RealTimeClock::play() {
  if (running_) return;
  elapsed_.start();
  running_ = true;
}

void RealTimeClock::pause() {
  origin_ = time();
  running_ = false;
}

void RealTimeClock::setTime(double seconds) {
  origin_ = seconds;
  if (running_) elapsed_.start();
}

double RealTimeClock::time() const {
  return running_ ? origin_ + static_cast<double>(elapsed_.nsecsElapsed()) * 1e-9 : origin_;
}

}  // namespace lacrima::player
