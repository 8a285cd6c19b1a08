#include <lacrima/editing/PresetLibrary.h>

#include <lacrima/common/FapTable.h>
#include <lacrima/common/JsonInput.h>
#include <lacrima/common/JsonWriter.h>
#include <lacrima/editing/ChannelLimits.h>

#include <QString>

#include <algorithm>
#include <cmath>
#include <set>

namespace lacrima::editing {
namespace {

// A presets file is a few kilobytes; anything this large is not one.
constexpr qint64 kMaxFileBytes = 16 * 1024 * 1024;
// The built-in file has a few dozen presets of a few keys each.
constexpr std::size_t kMaxPresets = 10'000;
constexpr std::size_t kMaxKeys = 10'000;

bool isValidId(const std::string& id) {
  return !id.empty() && std::all_of(id.begin(), id.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-';
  });
}

std::string text(const JsonValue& value) {
  if (!value.isString() || QString::fromStdString(value.string()).trimmed().isEmpty())
    value.fail("expected non-empty text, got " + value.describe());
  return value.string();
}

Keyframe readPose(const JsonValue& value) {
  const std::vector<JsonValue> values = value.members();
  if (values.empty()) value.fail("expected at least one FAP value, got an empty object");
  Keyframe key;
  for (const JsonValue& channel : values) {
    const std::string name = channel.name();
    const std::optional<int> fap = fapByName(name);
    if (!fap)
      channel.fail(
          "unknown FAP name; expected a name from the FAP table such as open_jaw, "
          "raise_l_i_eyebrow or tears_l_eye");
    const ChannelLimits limits = editLimits(*fap);
    const double v = channel.number();
    const bool whole = isTearChannel(*fap) || isHighLevelFap(*fap);
    if (v < limits.min || v > limits.max || (whole && v != std::floor(v))) {
      channel.fail(std::string("expected ") + (whole ? "a whole number" : "a number") + " in [" +
                   std::to_string(limits.min) + ", " + std::to_string(limits.max) +
                   "] (the editing range of " + name + "), got " + formatJsonNumber(v));
    }
    key.set(*fap, static_cast<float>(v));
  }
  return key;
}

std::vector<Keyframe> readSequence(const JsonValue& value) {
  if (!value.isArray()) value.fail("expected an array of keys, got " + value.describe());
  const std::vector<JsonValue> entries = value.array(kMaxKeys);
  if (entries.size() < 2)
    value.fail("expected at least two keys (use \"values\" for a single pose)");
  std::vector<Keyframe> keys;
  for (const JsonValue& entry : entries) {
    entry.rejectUnknownMembers({"time", "interpolation", "values"});
    const JsonValue time = entry.required("time");
    entry.required("values");
    const double seconds = time.number();
    if (keys.empty() && seconds != 0.0)
      time.fail("expected 0 for the first key, got " + formatJsonNumber(seconds));
    if (!keys.empty() && seconds <= keys.back().time) {
      time.fail("expected a time after the previous key's " + formatJsonNumber(keys.back().time) +
                " s, got " + formatJsonNumber(seconds));
    }
    if (seconds > 600.0) time.fail("expected at most 600 s, got " + formatJsonNumber(seconds));
    Keyframe key = readPose(entry["values"]);
    key.time = seconds;
    key.interpolation = Interpolation::Smooth;
    if (entry.has("interpolation"))
      key.interpolation = entry["interpolation"].oneOf({"linear", "smooth"}) == 0
                              ? Interpolation::Linear
                              : Interpolation::Smooth;
    keys.push_back(key);
  }
  return keys;
}

Preset readPreset(const JsonValue& entry) {
  entry.rejectUnknownMembers(
      {"id", "name", "category", "description", "expression", "values", "keys"});
  Preset preset;
  preset.id = text(entry.required("id"));
  if (!isValidId(preset.id))
    entry["id"].fail("expected lower-case letters, digits and '-', got \"" + preset.id + "\"");
  preset.name = text(entry.required("name"));
  preset.category = text(entry.required("category"));
  if (entry.has("description")) preset.description = text(entry["description"]);
  if (entry.has("expression")) {
    const JsonValue expression = entry["expression"];
    const double code = expression.number();
    if (code < 1 || code > 6 || code != std::floor(code))
      expression.fail(
          "expected an expression code 1..6 (joy, sadness, anger, fear, disgust, surprise), got " +
          formatJsonNumber(code));
    preset.expression = static_cast<int>(code);
  }
  const bool hasValues = entry.has("values");
  if (hasValues == entry.has("keys"))
    entry.fail("expected exactly one of \"values\" (a pose) and \"keys\" (a sequence)");
  if (hasValues) {
    Keyframe key = readPose(entry["values"]);
    key.interpolation = Interpolation::Smooth;
    preset.keys.push_back(key);
  } else {
    preset.keys = readSequence(entry["keys"]);
  }
  return preset;
}

std::vector<Preset> readPresets(const JsonValue& root) {
  if (!root.has("format"))
    root.fail("missing field \"format\"; this is not a Lacrima presets file");
  const JsonValue format = root["format"];
  if (!format.isString() || format.string() != PresetLibrary::kFormat)
    format.fail("expected \"" + std::string(PresetLibrary::kFormat) + "\", got " +
                format.describe());
  const JsonValue version = root.required("version");
  if (version.number() != PresetLibrary::kVersion)
    version.fail("expected " + std::to_string(PresetLibrary::kVersion) + ", got " +
                 version.describe());
  root.rejectUnknownMembers({"format", "version", "presets"});
  const JsonValue list = root.required("presets");
  if (!list.isArray()) list.fail("expected an array of presets, got " + list.describe());
  std::vector<Preset> presets;
  std::set<std::string> ids;
  std::set<int> expressions;
  for (const JsonValue& entry : list.array(kMaxPresets)) {
    Preset preset = readPreset(entry);
    if (!ids.insert(preset.id).second)
      entry["id"].fail("expected a unique id; \"" + preset.id + "\" is used by an earlier preset");
    if (preset.expression && !expressions.insert(*preset.expression).second)
      entry["expression"].fail("expected each expression code once; " +
                               std::to_string(*preset.expression) +
                               " is used by an earlier preset");
    if (preset.expression && preset.isSequence())
      entry["expression"].fail("expected only on a pose (\"values\"), not on a sequence");
    presets.push_back(std::move(preset));
  }
  return presets;
}

}  // namespace

PresetLibrary PresetLibrary::read(const JsonValue& root) {
  PresetLibrary library;
  library.presets_ = readPresets(root);
  return library;
}

PresetLibrary PresetLibrary::fromJson(std::string_view json, const std::string& displayName) {
  return read(JsonInput::parse(json, displayName).root());
}

PresetLibrary PresetLibrary::load(const std::string& path) {
  return read(JsonInput::load(path, {"presets file", kMaxFileBytes}).root());
}

PresetLibrary PresetLibrary::builtIn() { return load(std::string(kBuiltInPath)); }

const Preset* PresetLibrary::find(std::string_view id) const {
  for (const Preset& p : presets_)
    if (p.id == id) return &p;
  return nullptr;
}

const Preset* PresetLibrary::forExpression(int code) const {
  for (const Preset& p : presets_)
    if (p.expression == code) return &p;
  return nullptr;
}

std::vector<std::string> PresetLibrary::categories() const {
  std::vector<std::string> out;
  for (const Preset& p : presets_)
    if (std::find(out.begin(), out.end(), p.category) == out.end()) out.push_back(p.category);
  return out;
}

}  // namespace lacrima::editing
