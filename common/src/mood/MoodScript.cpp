#include <lacrima/common/JsonInput.h>
#include <lacrima/common/mood/MoodScript.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace lacrima::inline common {
namespace {

bool isIntensity(double value) { return std::isfinite(value) && value >= 0 && value <= 1; }

MoodScript read(const JsonValue& root) {
  root.rejectUnknownMembers({"format", "version", "keys"});
  if (root.has("format")) root["format"].oneOf({"lacrima-moods"});
  if (root.has("version")) root["version"].integer(1, 1);
  std::vector<MoodKey> keys;
  const std::vector<JsonValue> entries = root.required("keys").array(MoodScript::kMaxKeys);
  if (entries.empty()) root["keys"].fail("expected at least one key, got an empty array");
  keys.reserve(entries.size());
  for (const JsonValue& entry : entries) {
    if (!entry.isObject())
      entry.fail("expected a key {\"time\": seconds, \"sadness\": 0.8, ...}, got " +
                 entry.describe());
    entry.rejectUnknownMembers({"time", "sadness", "anger", "joy", "shame"});
    MoodKey key;
    key.time = entry.required("time").number(0, MoodScript::kMaxTime);
    if (!keys.empty() && !(key.time > keys.back().time)) {
      char previous[64];
      std::snprintf(previous, sizeof previous, "%g", keys.back().time);
      entry["time"].fail("expected a time after the previous key's " + std::string(previous) +
                         " s, got " + entry["time"].describe());
    }
    for (Mood mood : kMoods) {
      const std::string name(moodName(mood));
      if (entry.has(name)) key.levels[mood] = entry[name].number(0, 1);
    }
    keys.push_back(key);
  }
  return MoodScript(std::move(keys));
}

}  // namespace

MoodScript MoodScript::constant(const MoodLevels& levels) { return MoodScript({{0.0, levels}}); }

MoodScript::MoodScript(std::vector<MoodKey> keys) : keys_(std::move(keys)) {
  for (std::size_t i = 0; i < keys_.size(); ++i) {
    if (!std::isfinite(keys_[i].time) || (i > 0 && !(keys_[i].time > keys_[i - 1].time)))
      throw std::invalid_argument("mood keys need finite, increasing times");
    for (double level : keys_[i].levels.level)
      if (!isIntensity(level)) throw std::invalid_argument("mood intensities lie in [0, 1]");
  }
}

MoodScript MoodScript::parse(std::string_view json, const std::string& name) {
  return read(JsonInput::parse(json, name).root());
}

MoodScript MoodScript::load(const std::string& path) {
  return read(JsonInput::load(path, {"mood script", kMaxFileBytes}).root());
}

MoodLevels MoodScript::at(double seconds) const {
  if (keys_.empty()) return {};
  if (!(seconds > keys_.front().time)) return keys_.front().levels;
  if (seconds >= keys_.back().time) return keys_.back().levels;
  const auto next = std::upper_bound(keys_.begin(), keys_.end(), seconds,
                                     [](double t, const MoodKey& key) { return t < key.time; });
  const MoodKey& b = *next;
  const MoodKey& a = *(next - 1);
  const double u = (seconds - a.time) / (b.time - a.time);
  const double s = u * u * (3 - 2 * u);  // smoothstep: level at both keys, flat there
  MoodLevels levels;
  for (int m = 0; m < kMoodCount; ++m)
    levels.level[m] = a.levels.level[m] + s * (b.levels.level[m] - a.levels.level[m]);
  return levels;
}

}  // namespace lacrima::inline common
