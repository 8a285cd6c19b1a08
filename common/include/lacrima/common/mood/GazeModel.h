#pragma once
// Where the eyes look (docs/mood.md#blinks-and-gaze): down and away in sadness and shame,
// in fixations of [0.8, 3] s (judged) joined by saccades of kSaccade seconds. The side looked
// away to is drawn once per take; each fixation draws how far. A neutral face still moves its
// eyes a little between fixations.
#include <lacrima/common/FapChannels.h>
#include <lacrima/common/mood/MoodRandom.h>

#include <cstdint>

namespace lacrima::inline common {

class GazeModel {
 public:
  static constexpr double kSaccade = 0.06;  // s
  static constexpr double kDown = 20000;    // AU (11.5 degrees) at full sadness or shame
  static constexpr double kAway = 12000;    // AU (7 degrees) at most aside

  explicit GazeModel(std::uint64_t seed);

  void advance(double seconds, double sadness, double shame);
  void apply(FapValues& face) const;

  double pitch() const { return pitch_; }  // AU, positive down
  double yaw() const { return yaw_; }

 private:
  MoodRandom random_;
  double side_;  // +1 or -1
  bool started_ = false;
  double next_ = 0, moved_ = 0;
  double fromPitch_ = 0, fromYaw_ = 0, toPitch_ = 0, toYaw_ = 0;
  double awayDraw_ = 0, jitterPitch_ = 0, jitterYaw_ = 0;
  double pitch_ = 0, yaw_ = 0;
};

}  // namespace lacrima::inline common
