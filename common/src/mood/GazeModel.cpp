#include <lacrima/common/FapTable.h>
#include <lacrima/common/mood/GazeModel.h>

namespace lacrima::inline common {

GazeModel::GazeModel(std::uint64_t seed) : random_(seed) {
  side_ = random_.uniform() < 0.5 ? -1.0 : 1.0;
}

void GazeModel::advance(double seconds, double sadness, double shame) {
  const double low = sadness * 0.6 + shame;
  const double down = kDown * (low > 1 ? 1 : low);
  if (!started_ || seconds >= next_) {
    // a new fixation: the eyes jump from where they are
    fromPitch_ = pitch_;
    fromYaw_ = yaw_;
    moved_ = started_ ? next_ : seconds;
    next_ = moved_ + random_.uniform(0.8, 3.0);
    if (seconds >= next_) next_ = seconds + 0.8;
    awayDraw_ = random_.uniform(0.3, 1.0);
    jitterPitch_ = random_.uniform(-1500, 1500);
    jitterYaw_ = random_.uniform(-2500, 2500);
    started_ = true;
  }
  const double aside = sadness * 0.5 + shame;
  toPitch_ = down + jitterPitch_;
  toYaw_ = side_ * kAway * (aside > 1 ? 1 : aside) * awayDraw_ + jitterYaw_;
  const double u = smoothstep((seconds - moved_) / kSaccade);
  pitch_ = fromPitch_ + u * (toPitch_ - fromPitch_);
  yaw_ = fromYaw_ + u * (toYaw_ - fromYaw_);
}

void GazeModel::apply(FapValues& face) const {
  for (int fap : {25, 26}) face[channelIndex(fap)] += static_cast<float>(pitch_);
  for (int fap : {23, 24}) face[channelIndex(fap)] += static_cast<float>(yaw_);
}

}  // namespace lacrima::inline common
