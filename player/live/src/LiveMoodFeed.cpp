#include <lacrima/live/LiveMoodFeed.h>

#include <QTimer>

#include <algorithm>
#include <cmath>

namespace lacrima::live {

LiveMoodFeed::LiveMoodFeed(LiveSession& session, double rate, std::uint64_t seed, QObject* parent)
    : QObject(parent), session_(session), generator_(seed), timer_(new QTimer(this)) {
  timer_->setTimerType(Qt::PreciseTimer);
  const double interval = 1000.0 / std::clamp(std::isfinite(rate) ? rate : 30.0, 1.0, 1000.0);
  timer_->setInterval(std::max(1, static_cast<int>(std::lround(interval))));
  connect(timer_, &QTimer::timeout, this, &LiveMoodFeed::step);
  session_.setMoodHandler([this](const LiveMood& mood) { setMoods(mood.levels); });
  session_.setFrameHandler([this](const LiveFrame&) {
    driving_ = false;  // the newest message wins: the stream's face again
    timer_->stop();
  });
}

LiveMoodFeed::~LiveMoodFeed() = default;

void LiveMoodFeed::setMoods(const MoodLevels& levels) {
  moods_ = levels;
  if (driving_) return;
  driving_ = true;
  lastStep_ = liveClockSeconds();
  step();  // the face is the generator's from this line on, not from the next tick
  timer_->start();
}

void LiveMoodFeed::step() {
  if (!driving_) return;
  const double now = liveClockSeconds();
  if (generated_ > 0) takeSeconds_ += std::max(0.0, now - lastStep_);
  lastStep_ = now;
  session_.recordGenerated(generator_.step(takeSeconds_, moods_).channels, now);
  ++generated_;
}

}  // namespace lacrima::live
