#pragma once
// The moods the crying generator takes (docs/mood.md): the three moods people cry in that the
// 2009 thesis cites from Borgquist (anger, grief or sadness, joy), and shame, which its
// Table 2.1 names with anger as the cause of blushing. Each is an intensity in [0, 1].
#include <array>
#include <optional>
#include <string>
#include <string_view>

namespace lacrima::inline common {

enum class Mood { Sadness, Anger, Joy, Shame };
inline constexpr int kMoodCount = 4;
inline constexpr std::array<Mood, kMoodCount> kMoods{Mood::Sadness, Mood::Anger, Mood::Joy,
                                                     Mood::Shame};

std::string_view moodName(Mood mood);                   // "sadness", "anger", ...
std::optional<Mood> moodByName(std::string_view name);  // the inverse; nullopt for others

// One intensity per mood, each in [0, 1].
struct MoodLevels {
  std::array<double, kMoodCount> level{};

  double operator[](Mood mood) const { return level[static_cast<int>(mood)]; }
  double& operator[](Mood mood) { return level[static_cast<int>(mood)]; }
  bool operator==(const MoodLevels&) const = default;
};

// "sadness=0.8,anger=0.2": moods not named are 0. Throws std::invalid_argument naming the
// part that is wrong and what was expected (a known mood, '=', a number in [0, 1], a mood
// named once).
MoodLevels parseMoodLevels(std::string_view text);

// "sadness=0.8,anger=0.2" for the moods above 0 ("neutral" when none is).
std::string toString(const MoodLevels& levels);

// The crying presets of media/presets/presets.json as generator settings: the moods that cry
// that way (docs/mood.md#presets). The fixed presets still load and apply as they always did.
struct MoodPreset {
  std::string_view name;  // the preset's name
  MoodLevels levels;
};
inline constexpr int kMoodPresetCount = 5;
const std::array<MoodPreset, kMoodPresetCount>& moodPresets();

}  // namespace lacrima::inline common
