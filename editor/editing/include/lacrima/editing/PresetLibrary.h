#pragma once
// Presets: named poses and short key sequences the editor applies at the current time.
//
// File format (media/presets/presets.json; versioned JSON, every field checked):
//
//   { "format": "lacrima-presets", "version": 1,
//     "presets": [
//       { "id": "joy", "name": "Joy", "category": "Expressions", "expression": 1,
//         "description": "one sentence for the tooltip",
//         "values": { "raise_l_cornerlip": 140, "open_jaw": 60 } },          a pose
//       { "id": "sobbing-cycle", "name": "Sobbing cycle", "category": "Crying",
//         "description": "...",
//         "keys": [ { "time": 0,   "interpolation": "smooth", "values": { ... } },
//                   { "time": 0.4, "values": { ... } } ] } ] }                  a sequence
//
// - `id`: unique, lower-case letters, digits and '-'. `name`, `category`: non-empty text.
// - exactly one of `values` (a pose) and `keys` (times in seconds from where it is applied:
//   the first at 0, then strictly increasing; `interpolation` defaults to "smooth").
// - values are keyed by FAP name (as in project files) and must lie in the channel's editing
//   range (ChannelLimits.h); tear counts and FAP 1/2 codes are whole numbers.
// - `expression` (optional, 1..6): the FAP 2 code this pose spells out in low-level FAPs, so
//   the expression picker can apply it.
// Errors are FileError "file:line:column: json.path: what was expected".
#include <lacrima/common/Diagnostics.h>
#include <lacrima/common/JsonValue.h>
#include <lacrima/common/Keyframes.h>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lacrima::editing {

struct Preset {
  std::string id, name, category, description;
  std::optional<int> expression;  // FAP 2 code, 1..6
  // A pose is one key at time 0; a sequence has several, times relative to where it lands.
  std::vector<Keyframe> keys;

  bool isSequence() const { return keys.size() > 1; }
  double duration() const { return keys.empty() ? 0.0 : keys.back().time; }
};

class PresetLibrary {
 public:
  static constexpr std::string_view kFormat = "lacrima-presets";
  static constexpr int kVersion = 1;
  // The presets compiled into the editor (Qt resource copy of media/presets/presets.json).
  static constexpr std::string_view kBuiltInPath = ":/lacrima/presets.json";

  // Throws FileError naming `displayName`, the line and column, the JSON path and what was
  // expected.
  static PresetLibrary fromJson(std::string_view json, const std::string& displayName);
  static PresetLibrary read(const JsonValue& root);
  static PresetLibrary load(const std::string& path);  // also reads ":/..." resources
  static PresetLibrary builtIn();

  const std::vector<Preset>& presets() const { return presets_; }
  const Preset* find(std::string_view id) const;
  const Preset* forExpression(int code) const;  // the pose for FAP 2 code 1..6, if any
  std::vector<std::string> categories() const;  // in order of first appearance

 private:
  std::vector<Preset> presets_;
};

}  // namespace lacrima::editing
