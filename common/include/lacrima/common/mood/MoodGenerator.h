#pragma once
// The crying generator (docs/mood.md): mood intensities over time and a seed in, every channel
// the player plays out, frame by frame at any frame rate: the 68 FAPs, the tear channels 69/70
// and the face colours (redness, blush).
//
// One class per part, composed here and only here, in this order each frame:
//   the moods eased with a lag of kMoodLag (muscles do not jump);
//   TearProduction (its crying stage deepens the expression and tires the lids);
//   ExpressionBlend, SobCycle, LaughterRhythm, GazeModel, BlinkModel (blinks last: they close
//   the lids from wherever the rest left them);
//   FaceColour;
// then every channel is rounded to a whole number within generatedRange(fap).
// Each part draws from its own stream of the seed (streamSeed), so the same moods and seed give
// the same bits on every machine and thread count, and another seed another take.
#include <lacrima/common/FaceColours.h>
#include <lacrima/common/FapAnimation.h>
#include <lacrima/common/mood/BlinkModel.h>
#include <lacrima/common/mood/ExpressionBlend.h>
#include <lacrima/common/mood/FaceColour.h>
#include <lacrima/common/mood/GazeModel.h>
#include <lacrima/common/mood/LaughterRhythm.h>
#include <lacrima/common/mood/MoodScript.h>
#include <lacrima/common/mood/SobCycle.h>
#include <lacrima/common/mood/TearProduction.h>

#include <cstdint>
#include <functional>
#include <vector>

namespace lacrima::inline common {

struct MoodFrame {
  FapValues channels{};
  FaceColours colours;
};

// The range a generated channel stays in: the FAP table's editing range (FapInfo::sliderMin ..
// sliderMax), from 0 for unidirectional FAPs; FAP 1 and 2 stay 0.
struct ChannelRange {
  float min = 0, max = 0;
};
ChannelRange generatedRange(int fap);

class MoodGenerator {
 public:
  static constexpr double kMoodLag = 0.35;  // s, judged

  explicit MoodGenerator(std::uint64_t seed);

  // The face at `seconds` (not earlier than the last call; the first call starts the take)
  // with these moods (each clamped to [0, 1]; not a number counts as 0).
  MoodFrame step(double seconds, const MoodLevels& levels);

  const TearProduction& tears() const { return tears_; }
  const SobCycle& sobs() const { return sob_; }
  const LaughterRhythm& laughter() const { return laughter_; }
  const BlinkModel& blinks() const { return blinks_; }
  const GazeModel& gaze() const { return gaze_; }

 private:
  bool started_ = false;
  double last_ = 0;
  MoodLevels eased_;
  TearProduction tears_;
  ExpressionBlend expression_;
  SobCycle sob_;
  LaughterRhythm laughter_;
  GazeModel gaze_;
  BlinkModel blinks_;
  FaceColour colour_;
};

// A generated take: frames i = 0 .. n-1 at i / fps with n = floor(seconds fps) + 1, and the
// face colours of each frame.
struct MoodTake {
  FapAnimation animation;
  std::vector<FaceColours> colours;
};

inline constexpr double kMaxMoodSeconds = 86400;  // a day, as project keys

// Throws std::invalid_argument for fps outside (0, 1000], seconds outside [0, kMaxMoodSeconds]
// or more than kMaxBakedFrames frames, before allocating anything.
MoodTake generateMoodTake(const MoodScript& script, std::uint64_t seed, double seconds, double fps);
// The same with the moods of frame i read from moodsAt(i / fps) (a project's mood curves, the
// editor's Generate...); the script form is this with script.at.
MoodTake generateMoodTake(const std::function<MoodLevels(double)>& moodsAt, std::uint64_t seed,
                          double seconds, double fps);

}  // namespace lacrima::inline common
