#pragma once
// Mood intensities over time: what the crying generator follows (docs/mood.md).
//
// A script is a list of keys, each a time and an intensity per mood (moods a key does not name
// are 0 there). Between two keys every mood eases from one value to the next along a smoothstep
// (no kink at a key, never outside the two values); before the first key and after the last the
// values hold. A constant script is one key.
//
// The file form (moods.json):
//   { "format": "lacrima-moods", "version": 1,           (both optional)
//     "keys": [ { "time": 0, "sadness": 0 },
//               { "time": 2, "sadness": 0.8, "anger": 0.2 },
//               { "time": 20, "sadness": 0 } ] }
// Times are seconds in [0, 86400], strictly increasing; intensities in [0, 1]; at most
// kMaxKeys keys in a file of at most kMaxFileBytes. Anything else is a FileError naming the
// file, line, column, JSON path and what was expected.
#include <lacrima/common/mood/Moods.h>

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace lacrima::inline common {

struct MoodKey {
  double time = 0;  // seconds
  MoodLevels levels;
  bool operator==(const MoodKey&) const = default;
};

class MoodScript {
 public:
  static constexpr std::size_t kMaxKeys = 100000;
  static constexpr long long kMaxFileBytes = 16LL << 20;
  static constexpr double kMaxTime = 86400;  // a day, as project keys

  MoodScript() = default;  // neutral: every mood 0 at all times
  static MoodScript constant(const MoodLevels& levels);
  // Keys in increasing time order, each level in [0, 1]; std::invalid_argument otherwise.
  explicit MoodScript(std::vector<MoodKey> keys);

  static MoodScript parse(std::string_view json, const std::string& name);
  static MoodScript load(const std::string& path);

  const std::vector<MoodKey>& keys() const { return keys_; }
  MoodLevels at(double seconds) const;
  // The time of the last key (0 for a constant or neutral script).
  double endTime() const { return keys_.empty() ? 0.0 : keys_.back().time; }

 private:
  std::vector<MoodKey> keys_;
};

}  // namespace lacrima::inline common
