#include "PlaybackClock.h"

namespace lacrima::player {

void PlaybackClock::play() {
  if (running_) return;
  elapsed_.start();
  running_ = true;
}

void PlaybackClock::pause() {
  origin_ = time();
  running_ = false;
}

void PlaybackClock::setTime(double seconds) {
  origin_ = seconds;
  if (running_) elapsed_.start();
}

double PlaybackClock::time() const {
  return running_ ? origin_ + static_cast<double>(elapsed_.nsecsElapsed()) * 1e-9 : origin_;
}

}  // namespace lacrima::player
