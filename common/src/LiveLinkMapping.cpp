#include <lacrima/common/AtomicSave.h>
#include <lacrima/common/FapTable.h>
#include <lacrima/common/JsonInput.h>
#include <lacrima/common/JsonWriter.h>
#include <lacrima/common/LiveLinkMapping.h>

#include <algorithm>
#include <cmath>

namespace lacrima::inline common {

namespace {

constexpr const char* kFormat = "lacrima-livelink-mapping";
constexpr qint64 kMaxFileBytes = 1 << 20;

LiveLinkMapping readMapping(const JsonValue& root) {
  root.rejectUnknownMembers({"format", "version", "comment", "rows"});
  if (root["format"].string() != kFormat)
    root["format"].fail(std::string("expected \"") + kFormat + "\", got " +
                        root["format"].describe());
  root["version"].integer(1, 1);
  LiveLinkMapping mapping;
  for (const JsonValue& row : root.required("rows").array(LiveLinkMapping::kMaxRows)) {
    row.rejectUnknownMembers({"from", "to", "gain", "comment"});
    LiveLinkMappingRow r;
    const JsonValue from = row.required("from");
    r.value = liveLinkValueIndex(from.string());
    if (r.value < 0)
      from.fail("expected a Live Link value name (jawOpen, headYaw, ...), got " + from.describe());
    const JsonValue to = row.required("to");
    const std::optional<int> fap = fapByName(to.string());
    if (!fap || isHighLevelFap(*fap) || isTearChannel(*fap))
      to.fail("expected a FAP name from open_jaw (3) to pull_r_ear (68), got " + to.describe());
    r.channel = *fap;
    r.gain = row.required("gain").number(-LiveLinkMapping::kMaxGain, LiveLinkMapping::kMaxGain);
    mapping.rows.push_back(r);
  }
  return mapping;
}

}  // namespace

ChannelMask LiveLinkMapping::channels() const {
  ChannelMask mask;
  for (const LiveLinkMappingRow& row : rows)
    mask.set(static_cast<std::size_t>(channelIndex(row.channel)));
  return mask;
}

FapValues LiveLinkMapping::retarget(const LiveLinkPacket& packet) const {
  std::array<double, kChannelCount> sums{};
  for (const LiveLinkMappingRow& row : rows) {
    sums[static_cast<std::size_t>(channelIndex(row.channel))] +=
        row.gain * packet.values[static_cast<std::size_t>(row.value)];
  }
  FapValues values{};
  for (std::size_t c = 0; c < values.size(); ++c)
    values[c] =
        static_cast<float>(std::isfinite(sums[c]) ? std::clamp(sums[c], -kMaxGain, kMaxGain) : 0.0);
  return values;
}

LiveLinkMapping LiveLinkMapping::load(const std::string& path) {
  return readMapping(JsonInput::load(path, {"Live Link mapping", kMaxFileBytes}).root());
}

LiveLinkMapping LiveLinkMapping::parse(std::string_view text, const std::string& name) {
  return readMapping(JsonInput::parse(text, name).root());
}

std::string LiveLinkMapping::toJson() const {
  JsonWriter out;
  out.beginObject();
  out.field("format", kFormat);
  out.field("version", 1);
  out.key("rows");
  out.beginArray();
  for (const LiveLinkMappingRow& row : rows) {
    out.beginObject();
    out.field("from", liveLinkValueNames()[static_cast<std::size_t>(row.value)]);
    out.field("to", fapInfo(row.channel).name);
    out.field("gain", row.gain);
    out.endObject();
  }
  out.endArray();
  out.endObject();
  return std::move(out).finish();
}

void LiveLinkMapping::save(const std::string& path) const { saveAtomically(path, toJson()); }

}  // namespace lacrima::inline common
