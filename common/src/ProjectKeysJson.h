#pragma once
// The keys and layers of a project file, read and written. Private to lacrima_common:
// ProjectDocument reads the rest of the file and hands the "keys" array here.
//
// A key:
//   { "time": 0.5, "interpolation": "smooth", "values": { "open_jaw": 120 },
//     "shapes": { "open_jaw": { "interpolation": "bezier", "handles": "aligned",
//                               "in": [-0.1, 40], "out": [0.2, -80] } } }      (version 2)
// "shapes" lists only channels whose shape is not the key's default (KeyShape), so a file
// of version 1 and the same keys written again differ only in the version number. Version 1
// files know only the linear and smooth interpolations.
#include <lacrima/common/JsonValue.h>
#include <lacrima/common/JsonWriter.h>
#include <lacrima/common/Keyframes.h>
#include <lacrima/common/PoseLayer.h>
#include <lacrima/common/mood/MoodLayer.h>

#include <string>
#include <string_view>
#include <vector>

namespace lacrima::inline common::detail {

// The shortest decimal that reads back as `value` (see the definition).
double doubleForFloat(float value);

// "; did you mean open_jaw?" for a near miss of a FAP name, else "".
std::string fapNameHint(std::string_view name);

// A channel's value: tear channels whole particles in [0, kMaxTearParticles], others within
// +-1e7 (far beyond any face; catches unit mix-ups).
float readChannelValue(int fap, const JsonValue& value);

// The interpolations a file of schema `version` may name.
Interpolation readInterpolation(const JsonValue& value, int version);

void writeKeys(JsonWriter& out, const KeyframeSequence& keys);
KeyframeSequence readKeys(const JsonValue& value, Interpolation defaultMode, int version);

// A curve's keys (IntensityCurve.h): [{ "time", "value", "interpolation" }], each value in
// [min, max]; at most 100,000 keys.
void writeIntensityKeys(JsonWriter& out, const std::vector<IntensityKey>& keys);
std::vector<IntensityKey> readIntensityKeys(const JsonValue& value, int version, double min,
                                            double max);

// Layers (PoseLayer.h): [{ "name", "muted", "pose": {channel: value}, "intensity":
// [{ "time", "value", "interpolation" }] }]. A pose may not hold FAP 1 or 2.
void writeLayers(JsonWriter& out, const std::vector<PoseLayer>& layers);
std::vector<PoseLayer> readLayers(const JsonValue& value, int version);

// The mood layer (MoodLayer.h, MoodLayerJson.cpp): { "seed", "start", "end", "muted" }, the
// seed a whole number up to MoodLayer::kMaxSeed, 0 <= start < end <= 86400 s. Its length in
// frames is bounded where the project is read to be baked (it is part of bakeRange()), and by
// generateMoodTake before anything is allocated.
void writeMoodLayer(JsonWriter& out, const MoodLayer& layer);
MoodLayer readMoodLayer(const JsonValue& value, int version);

}  // namespace lacrima::inline common::detail
