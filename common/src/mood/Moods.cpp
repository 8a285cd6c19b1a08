#include <lacrima/common/mood/Moods.h>

#include <charconv>
#include <cmath>
#include <stdexcept>

namespace lacrima::inline common {
namespace {

constexpr std::array<std::string_view, kMoodCount> kNames{"sadness", "anger", "joy", "shame"};

std::string knownMoods() { return "sadness, anger, joy or shame"; }

}  // namespace

std::string_view moodName(Mood mood) { return kNames[static_cast<int>(mood)]; }

std::optional<Mood> moodByName(std::string_view name) {
  for (Mood mood : kMoods)
    if (moodName(mood) == name) return mood;
  return std::nullopt;
}

MoodLevels parseMoodLevels(std::string_view text) {
  MoodLevels levels;
  std::array<bool, kMoodCount> named{};
  if (text.empty()) throw std::invalid_argument("expected mood=intensity, got nothing");
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    const std::string_view part = text.substr(start, comma - start);
    const std::size_t equals = part.find('=');
    if (equals == std::string_view::npos)
      throw std::invalid_argument("expected mood=intensity (e.g. sadness=0.8), got '" +
                                  std::string(part) + "'");
    const std::string_view name = part.substr(0, equals);
    const std::optional<Mood> mood = moodByName(name);
    if (!mood)
      throw std::invalid_argument("unknown mood '" + std::string(name) + "'; expected " +
                                  knownMoods());
    if (named[static_cast<int>(*mood)])
      throw std::invalid_argument("mood '" + std::string(name) + "' is named twice");
    named[static_cast<int>(*mood)] = true;
    const std::string_view number = part.substr(equals + 1);
    double value = 0;
    const auto [end, ec] = std::from_chars(number.data(), number.data() + number.size(), value);
    if (ec != std::errc() || end != number.data() + number.size() || number.empty() ||
        !std::isfinite(value) || value < 0 || value > 1)
      throw std::invalid_argument(std::string(name) + ": expected an intensity from 0 to 1, got '" +
                                  std::string(number) + "'");
    levels[*mood] = value;
    start = comma + 1;
  }
  return levels;
}

const std::array<MoodPreset, kMoodPresetCount>& moodPresets() {
  // Judged from the generator's own thresholds (docs/mood.md): welling needs a drive above 0.2
  // and spills 5 s later; sobs deepen from sadness 0.3 to 0.9; anger sobs above 0.6; joy
  // weeps above 0.6 and laughs above 0.4.
  static const std::array<MoodPreset, kMoodPresetCount> presets{{
      {"Tears welling", MoodLevels{{0.3, 0, 0, 0}}},
      {"Sad crying", MoodLevels{{0.8, 0, 0, 0}}},
      {"Angry crying", MoodLevels{{0.2, 0.9, 0, 0}}},
      {"Tears of joy", MoodLevels{{0, 0, 0.95, 0}}},
      {"Sobbing cycle", MoodLevels{{1, 0, 0, 0}}},
  }};
  return presets;
}

std::string toString(const MoodLevels& levels) {
  std::string out;
  for (Mood mood : kMoods) {
    if (!(levels[mood] > 0)) continue;
    char buffer[32];
    const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, levels[mood]);
    if (!out.empty()) out += ',';
    out +=
        std::string(moodName(mood)) + '=' + std::string(buffer, ec == std::errc() ? end : buffer);
  }
  return out.empty() ? "neutral" : out;
}

}  // namespace lacrima::inline common
