#pragma once
// How Live Link Face values become FAPs: a table of rows "value -> channel, gain", summed per
// channel (FAP = sum of gain x value). It ships as media/livelink-mapping.json, documented in
// docs/live.md; users edit the gains there or in the player (Live > Mapping...) and save their
// own copy.
//
//   { "format": "lacrima-livelink-mapping", "version": 1,
//     "rows": [ { "from": "jawOpen", "to": "open_jaw", "gain": 700 }, ... ] }
//
// `from` is one of the 61 Live Link values (liveLinkValueNames()), `to` a FAP name of FapTable
// (tear channels excluded: a phone does not see tears), `gain` a finite number within +-1e7.
#include <lacrima/common/FapChannels.h>
#include <lacrima/common/LiveLinkPacket.h>

#include <string>
#include <vector>

namespace lacrima::inline common {

struct LiveLinkMappingRow {
  int value = 0;    // index into LiveLinkPacket::values
  int channel = 0;  // FAP number, 3..68
  double gain = 0;
  bool operator==(const LiveLinkMappingRow&) const = default;
};

struct LiveLinkMapping {
  static constexpr std::size_t kMaxRows = 1024;
  static constexpr double kMaxGain = 1e7;

  std::vector<LiveLinkMappingRow> rows;

  // The channels some row writes: a retargeted frame masks exactly these.
  ChannelMask channels() const;
  // FAP values of one packet: each mapped channel the sum of its rows, every other channel 0.
  // Results are clamped to +-1e7 (finite whatever the gains).
  FapValues retarget(const LiveLinkPacket& packet) const;

  // Throws FileError "file:line:column: rows[3].to: expected a FAP name, got ..." and the like.
  static LiveLinkMapping load(const std::string& path);
  static LiveLinkMapping parse(std::string_view text, const std::string& name);
  std::string toJson() const;
  void save(const std::string& path) const;  // atomic
  bool operator==(const LiveLinkMapping&) const = default;
};

}  // namespace lacrima::inline common
