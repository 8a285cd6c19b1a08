#pragma once
// A project's mood curves (docs/mood.md#mood-curves-in-projects): sadness, anger, joy and shame
// keyed over project time like a layer's intensity, each in [0, 1]. They are what the editor's
// Generate crying... can follow instead of constant moods, and what a project's mood layer
// follows (MoodLayer.h); by themselves they never play, and a .fap export never carries them.
#include <lacrima/common/IntensityCurve.h>
#include <lacrima/common/mood/Moods.h>

#include <array>

namespace lacrima::inline common {

struct MoodCurves {
  std::array<IntensityCurve, kMoodCount> curves;

  const IntensityCurve& operator[](Mood mood) const { return curves[static_cast<int>(mood)]; }
  IntensityCurve& operator[](Mood mood) { return curves[static_cast<int>(mood)]; }
  bool empty() const;
  // Every mood at `seconds`, clamped to [0, 1] (a mood without keys is 0; not a number: 0).
  MoodLevels at(double seconds) const;
  // The first and last key of any mood (0, 0 without keys).
  double startTime() const;
  double endTime() const;
  bool operator==(const MoodCurves&) const = default;
};

}  // namespace lacrima::inline common
