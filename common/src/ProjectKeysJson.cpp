#include "ProjectKeysJson.h"

#include <lacrima/common/FapTable.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <numeric>
#include <vector>

namespace lacrima::inline common::detail {
namespace {

// A key's time: seconds from 0 to kMaxKeyTime (a day).
double readKeyTime(const JsonValue& time) {
  const double seconds = time.isNumber() ? time.number() : -1.0;
  if (!(seconds >= 0.0 && seconds <= kMaxKeyTime))
    time.fail("expected a time in seconds from 0 to " + formatJsonNumber(kMaxKeyTime) + ", got " +
              time.describe());
  return seconds;
}

constexpr double kMaxChannelMagnitude = 1e7;
// A key a frame of an hour at 240 fps; a 64 MiB file could spell out a few million empty ones.
constexpr std::size_t kMaxKeys = 1'000'000;
constexpr double kSameKeyTime = 1e-9;  // as KeyframeSequence: closer keys would merge
// A handle reaching further than a day along time, or further than any value reaches, is a
// broken file; the curve clamps handles to their segment anyway.
constexpr double kMaxHandleSeconds = 86400.0;
constexpr double kMaxHandleValue = 2.0 * kMaxChannelMagnitude;

void writeHandle(JsonWriter& out, const Handle& handle) {
  out.beginArray();
  out.number(handle.dt);
  out.number(handle.dv);
  out.endArray();
}

void writeShape(JsonWriter& out, const KeyShape& shape) {
  out.beginObject();
  out.key("interpolation");
  out.string(toString(shape.interpolation));
  out.key("handles");
  out.string(toString(shape.handles));
  if (shape.handles != HandleType::Auto) {
    out.key("in");
    writeHandle(out, shape.in);
    out.key("out");
    writeHandle(out, shape.out);
  }
  out.endObject();
}

void writeKey(JsonWriter& out, const Keyframe& key) {
  out.beginObject();
  out.key("time");
  out.number(key.time);
  out.key("interpolation");
  out.string(toString(key.interpolation));
  out.key("values");
  out.beginObject();
  for (int fap = 1; fap <= kChannelCount; ++fap) {
    if (!key.has(fap)) continue;
    out.key(fapInfo(fap).name);
    out.number(doubleForFloat(key.value(fap)));
  }
  out.endObject();
  if (!key.ownShapes().empty()) {
    out.key("shapes");
    out.beginObject();
    for (const auto& [index, shape] : key.ownShapes()) {
      if (!key.channels.test(index)) continue;
      out.key(fapInfo(fapNumber(index)).name);
      writeShape(out, shape);
    }
    out.endObject();
  }
  out.endObject();
}

Handle readHandle(const JsonValue& value, bool forward) {
  if (!value.isArray() || value.size() != 2) {
    value.fail("expected [seconds, value], got " + value.describe());
  }
  const std::vector<double> pair = value.numbers(2);
  const bool rightWay = forward ? pair[0] >= 0.0 : pair[0] <= 0.0;
  if (!rightWay || std::abs(pair[0]) > kMaxHandleSeconds || std::abs(pair[1]) > kMaxHandleValue) {
    value.fail(std::string("expected a handle pointing ") + (forward ? "forward" : "back") +
               " in time: [" + (forward ? "0" : "-86400") + ".." + (forward ? "86400" : "0") +
               " s, -2e7..2e7], got " + value.describe());
  }
  return {pair[0], pair[1]};
}

void readShapes(const JsonValue& shapes, Keyframe& key) {
  for (const JsonValue& entry : shapes.members()) {
    const std::string name = entry.name();
    const std::optional<int> fap = fapByName(name);
    if (!fap) entry.fail("unknown FAP name" + fapNameHint(name));
    if (!key.has(*fap)) entry.fail("a shape for a channel the key's \"values\" do not set");
    entry.rejectUnknownMembers({"interpolation", "handles", "in", "out"});
    KeyShape shape{key.interpolation, HandleType::Auto, {}, {}};
    if (entry.has("interpolation"))
      shape.interpolation = readInterpolation(entry["interpolation"], 2);
    if (entry.has("handles")) {
      shape.handles = static_cast<HandleType>(entry["handles"].oneOf({"auto", "aligned", "free"}));
    }
    if (shape.handles != HandleType::Auto) {
      shape.in = readHandle(entry.required("in"), false);
      shape.out = readHandle(entry.required("out"), true);
    }
    key.setShape(*fap, shape);
  }
}

Keyframe readKey(const JsonValue& value, Interpolation defaultMode, int version) {
  if (version >= 2) {
    value.rejectUnknownMembers({"time", "interpolation", "values", "shapes"});
  } else {
    value.rejectUnknownMembers({"time", "interpolation", "values"});
  }
  Keyframe key;
  key.time = readKeyTime(value.required("time"));
  key.interpolation =
      value.has("interpolation") ? readInterpolation(value["interpolation"], version) : defaultMode;
  const JsonValue values = value["values"];
  if (values.missing()) values.fail("missing");
  for (const JsonValue& channel : values.members()) {
    const std::string name = channel.name();
    const std::optional<int> fap = fapByName(name);
    if (!fap) channel.fail("unknown FAP name" + fapNameHint(name));
    key.set(*fap, readChannelValue(*fap, channel));
  }
  if (value.has("shapes")) readShapes(value["shapes"], key);
  return key;
}

void rejectDuplicateTimes(const std::vector<Keyframe>& keys, const std::vector<JsonValue>& values) {
  std::vector<std::size_t> order(keys.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return keys[a].time < keys[b].time; });
  for (std::size_t i = 1; i < order.size(); ++i) {
    const std::size_t first = std::min(order[i - 1], order[i]);
    const std::size_t second = std::max(order[i - 1], order[i]);
    if (keys[second].time - keys[first].time < kSameKeyTime &&
        keys[first].time - keys[second].time < kSameKeyTime) {
      values[second]["time"].fail(formatJsonNumber(keys[second].time) + " repeats the time of " +
                                  values[first].path().toString());
    }
  }
}

}  // namespace

float readChannelValue(int fap, const JsonValue& value) {
  const double v = value.isNumber() ? value.number() : std::nan("");
  if (isTearChannel(fap)) {
    if (!(v >= 0.0 && v <= kMaxTearParticles && v == std::floor(v))) {
      value.fail("expected a whole number of particles in [0, " +
                 std::to_string(kMaxTearParticles) + "], got " + value.describe());
    }
  } else if (!(std::abs(v) <= kMaxChannelMagnitude)) {
    value.fail("expected a number in [-1e7, 1e7], got " + value.describe());
  }
  return static_cast<float>(v);
}

KeyframeSequence readKeys(const JsonValue& value, Interpolation defaultMode, int version) {
  const std::vector<JsonValue> list = value.array(kMaxKeys);
  std::vector<Keyframe> result;
  result.reserve(list.size());
  for (const JsonValue& entry : list) result.push_back(readKey(entry, defaultMode, version));
  rejectDuplicateTimes(result, list);
  return KeyframeSequence(std::move(result));
}

// The double to write for a float value: the shortest decimal that reads back as the float
// ("0.1", not "0.10000000149011612"), provided text -> double -> float returns exactly the
// float; otherwise (a double rounding near a tie) the float's exact double value.
double doubleForFloat(float value) {
  std::array<char, 32> buffer{};
  const auto written = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  double shortest = 0.0;
  const auto read = std::from_chars(buffer.data(), written.ptr, shortest);
  if (read.ec == std::errc{} && static_cast<float>(shortest) == value) return shortest;
  return static_cast<double>(value);
}

namespace {

// Edit distance, to suggest the FAP name a typo was probably meant to be.
std::size_t editDistance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  std::iota(row.begin(), row.end(), std::size_t{0});
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t substitute = diagonal + (a[i - 1] == b[j - 1] ? 0 : 1);
      diagonal = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, substitute});
    }
  }
  return row[b.size()];
}

}  // namespace

std::string fapNameHint(std::string_view name) {
  std::string_view best;
  std::size_t bestDistance = 3;  // suggest only near misses
  for (const FapInfo& info : fapTable()) {
    const std::size_t distance = editDistance(name, info.name);
    if (distance < bestDistance) {
      bestDistance = distance;
      best = info.name;
    }
  }
  return best.empty() ? std::string() : "; did you mean " + std::string(best) + "?";
}

Interpolation readInterpolation(const JsonValue& value, int version) {
  if (version < 2) {
    return value.oneOf({"linear", "smooth"}) == 0 ? Interpolation::Linear : Interpolation::Smooth;
  }
  static constexpr std::array kModes{Interpolation::Linear, Interpolation::Smooth,
                                     Interpolation::Constant, Interpolation::Bezier};
  return kModes[value.oneOf({"linear", "smooth", "constant", "bezier"})];
}

void writeKeys(JsonWriter& out, const KeyframeSequence& keys) {
  out.beginArray();
  for (const Keyframe& key : keys.keys()) writeKey(out, key);
  out.endArray();
}

namespace {

// Far more than anyone layers; bounds what a file can make us allocate.
constexpr std::size_t kMaxLayers = 1000;
constexpr std::size_t kMaxIntensityKeys = 100'000;
// An intensity scales a pose; beyond +-100 times a pose no face survives.
constexpr double kMaxIntensity = 100.0;

void writeLayer(JsonWriter& out, const PoseLayer& layer) {
  out.beginObject();
  out.key("name");
  out.string(layer.name);
  out.key("muted");
  out.boolean(layer.muted);
  out.key("pose");
  out.beginObject();
  for (int fap = 1; fap <= kChannelCount; ++fap) {
    if (!layer.channels().test(channelIndex(fap))) continue;
    out.key(fapInfo(fap).name);
    out.number(doubleForFloat(layer.poseValue(fap)));
  }
  out.endObject();
  out.key("intensity");
  writeIntensityKeys(out, layer.intensityKeys());
  out.endObject();
}

PoseLayer readLayer(const JsonValue& value, int version) {
  value.rejectUnknownMembers({"name", "muted", "pose", "intensity"});
  PoseLayer layer;
  if (value.has("name")) layer.name = value["name"].string();
  if (value.has("muted")) layer.muted = value["muted"].boolean();
  for (const JsonValue& channel : value.required("pose").members()) {
    const std::string name = channel.name();
    const std::optional<int> fap = fapByName(name);
    if (!fap) channel.fail("unknown FAP name" + fapNameHint(name));
    if (isHighLevelFap(*fap)) channel.fail("viseme and expression codes cannot be layered");
    layer.setPoseValue(*fap, readChannelValue(*fap, channel));
  }
  layer.setIntensityKeys(
      readIntensityKeys(value.required("intensity"), version, -kMaxIntensity, kMaxIntensity));
  return layer;
}

IntensityKey readIntensityKey(const JsonValue& value, int version, double min, double max) {
  value.rejectUnknownMembers({"time", "value", "interpolation"});
  IntensityKey key;
  key.time = readKeyTime(value.required("time"));
  key.value = value.required("value").number(min, max);
  if (value.has("interpolation")) {
    key.interpolation = readInterpolation(value["interpolation"], version);
  }
  return key;
}

}  // namespace

void writeIntensityKeys(JsonWriter& out, const std::vector<IntensityKey>& keys) {
  out.beginArray();
  for (const IntensityKey& key : keys) {
    out.beginObject();
    out.key("time");
    out.number(key.time);
    out.key("value");
    out.number(key.value);
    out.key("interpolation");
    out.string(toString(key.interpolation));
    out.endObject();
  }
  out.endArray();
}

std::vector<IntensityKey> readIntensityKeys(const JsonValue& value, int version, double min,
                                            double max) {
  std::vector<IntensityKey> keys;
  const std::vector<JsonValue> list = value.array(kMaxIntensityKeys);
  keys.reserve(list.size());
  for (const JsonValue& entry : list) keys.push_back(readIntensityKey(entry, version, min, max));
  return keys;
}

void writeLayers(JsonWriter& out, const std::vector<PoseLayer>& layers) {
  out.beginArray();
  for (const PoseLayer& layer : layers) writeLayer(out, layer);
  out.endArray();
}

std::vector<PoseLayer> readLayers(const JsonValue& value, int version) {
  std::vector<PoseLayer> layers;
  for (const JsonValue& entry : value.array(kMaxLayers))
    layers.push_back(readLayer(entry, version));
  return layers;
}

}  // namespace lacrima::inline common::detail
