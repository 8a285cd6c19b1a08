#include <lacrima/editing/FrameStepClock.h>

#include <lacrima/editing/EditorModel.h>

#include <algorithm>
#include <cmath>

namespace lacrima::editing {

FrameStepClock::FrameStepClock(EditorModel& model, QObject* parent)
    : QObject(parent), model_(model) {
  timer_.setTimerType(Qt::PreciseTimer);
  connect(&timer_, &QTimer::timeout, this, &FrameStepClock::advance);
  connect(&model_, &EditorModel::documentReset, this, &FrameStepClock::pause);
}

void FrameStepClock::play() {
  if (isPlaying()) return;
  // What the player plays: the keys, and the layers beyond them (a crying layer alone plays).
  const auto [start, end] = model_.document().bakeRange();
  if (!(end > start)) {
    emit model_.message(tr("Nothing to play yet: key at least two times"));
    return;
  }
  // Playing from the end starts over.
  if (model_.currentTime() >= end - 1e-9) model_.setCurrentTimeExact(start);
  timer_.start(static_cast<int>(std::lround(1000.0 / rate_)));
  emit playingChanged(true);
}

void FrameStepClock::pause() {
  if (!isPlaying()) return;
  timer_.stop();
  // Land on the frame grid so an edit after stopping keys a whole frame.
  model_.setCurrentTime(model_.currentTime());
  emit playingChanged(false);
}

void FrameStepClock::toggle() { isPlaying() ? pause() : play(); }

void FrameStepClock::setRate(double framesPerSecond) {
  if (!std::isfinite(framesPerSecond)) return;
  framesPerSecond = std::clamp(framesPerSecond, 1.0, 120.0);
  if (framesPerSecond == rate_) return;
  rate_ = framesPerSecond;
  if (isPlaying()) timer_.setInterval(static_cast<int>(std::lround(1000.0 / rate_)));
}

void FrameStepClock::setLoop(bool on) { loop_ = on; }

void FrameStepClock::advance() {
  const auto [start, end] = model_.document().bakeRange();
  const double dt = 1.0 / rate_;
  double next = model_.currentTime() + dt;
  if (next > end + 1e-9) {
    if (!loop_) {
      model_.setCurrentTimeExact(end);
      pause();
      return;
    }
    next = start;
  }
  model_.setCurrentTimeExact(next);
  emit ticked(dt);
}

}  // namespace lacrima::editing
