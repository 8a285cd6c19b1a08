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
  const auto& keys = model_.document().keys;
  if (keys.keys().size() < 2) {
    emit model_.message(tr("Nothing to play yet: key at least two times"));
    return;
  }
  // Playing from the end starts over.
  if (model_.currentTime() >= keys.endTime() - 1e-9) model_.setCurrentTimeExact(keys.startTime());
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
  const auto& keys = model_.document().keys;
  const double dt = 1.0 / rate_;
  double next = model_.currentTime() + dt;
  if (next > keys.endTime() + 1e-9) {
    if (!loop_) {
      model_.setCurrentTimeExact(keys.endTime());
      pause();
      return;
    }
    next = keys.startTime();
  }
  model_.setCurrentTimeExact(next);
  emit ticked(dt);
}

}  // namespace lacrima::editing
