#pragma once
// The facial expression of the moods (docs/mood.md#expression): each mood has the MPEG-4
// expression's low-level FAPs (media/presets/presets.json: sadness, anger, joy) and the
// crying form of that expression (the presets' sad crying, angry crying and tears of joy);
// shame has one pose (gaze and head down and aside, lips pressed). A mood at level l adds
//   w (1 - c) expression + w c crying,   w = l / max(1, sum of levels),
// c the crying stage (TearProduction::crying), so mixed moods never add up past one full
// expression. Micro-variation: every channel the blend moves wanders by up to 8 % of its value
// on smooth noise of its own (about one wiggle per 1.3 s), and the head sways idly by up to
// 600 AU (0.34 degrees) even on a neutral face, so no two seconds are the same.
#include <lacrima/common/FapChannels.h>
#include <lacrima/common/mood/Moods.h>

#include <cstdint>

namespace lacrima::inline common {

class ExpressionBlend {
 public:
  explicit ExpressionBlend(std::uint64_t seed) : seed_(seed) {}

  // Adds the blended expression at time `seconds` to `face`.
  void apply(const MoodLevels& levels, double crying, double seconds, FapValues& face) const;

  // A mood's pose at intensity 1, before or in crying (crying in [0, 1]).
  static FapValues pose(Mood mood, double crying);

 private:
  std::uint64_t seed_;
};

}  // namespace lacrima::inline common
