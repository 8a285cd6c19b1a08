// The project's "moodLayer" (MoodLayer.h), read and written (ProjectKeysJson.h).
#include "ProjectKeysJson.h"

#include <cmath>
#include <string>

namespace lacrima::inline common::detail {
namespace {

double readLayerTime(const JsonValue& value, double after) {
  const double seconds = value.isNumber() ? value.number() : std::nan("");
  if (!(seconds >= after && seconds <= kMaxMoodSeconds))
    value.fail("expected a time in seconds from " + formatJsonNumber(after) + " to " +
               formatJsonNumber(kMaxMoodSeconds) + ", got " + value.describe());
  return seconds;
}

}  // namespace

void writeMoodLayer(JsonWriter& out, const MoodLayer& layer) {
  out.beginObject();
  out.key("seed");
  out.number(static_cast<double>(layer.seed));
  out.key("start");
  out.number(layer.start);
  out.key("end");
  out.number(layer.end);
  out.key("muted");
  out.boolean(layer.muted);
  out.endObject();
}

MoodLayer readMoodLayer(const JsonValue& value, int version) {
  if (version < 2) value.fail("a mood layer needs a project of version 2 or later");
  if (!value.isObject())
    value.fail(
        "expected an object {\"seed\": n, \"start\": s, \"end\": s, \"muted\": false}, got " +
        value.describe());
  value.rejectUnknownMembers({"seed", "start", "end", "muted"});
  MoodLayer layer;
  const JsonValue seed = value.required("seed");
  const double number = seed.isNumber() ? seed.number() : -1.0;
  if (!(number >= 0 && number <= static_cast<double>(MoodLayer::kMaxSeed) &&
        number == std::floor(number)))
    seed.fail("expected a whole number from 0 to " + std::to_string(MoodLayer::kMaxSeed) +
              ", got " + seed.describe());
  layer.seed = static_cast<std::uint64_t>(number);
  layer.start = readLayerTime(value.required("start"), 0.0);
  const JsonValue end = value.required("end");
  layer.end = readLayerTime(end, layer.start);
  if (layer.end == layer.start)
    end.fail("expected a time after the start's " + formatJsonNumber(layer.start) + " s, got " +
             end.describe());
  if (value.has("muted")) layer.muted = value["muted"].boolean();
  return layer;
}

}  // namespace lacrima::inline common::detail
