#include <lacrima/editor/DopeSheetRows.h>

#include <lacrima/common/FapTable.h>

namespace lacrima::editor {
namespace {

std::vector<int> keysSetting(const KeyframeSequence& keys, const ChannelMask& channels) {
  std::vector<int> out;
  const auto& all = keys.keys();
  for (std::size_t i = 0; i < all.size(); ++i)
    if ((all[i].channels & channels).any()) out.push_back(static_cast<int>(i));
  return out;
}

}  // namespace

std::vector<DopeSheetRow> buildDopeSheetRows(const KeyframeSequence& keys,
                                             const DopeSheetRowOptions& options) {
  ChannelMask animated;
  for (const Keyframe& key : keys.keys()) animated |= key.channels;
  const ChannelMask visible = options.onlyAnimated ? (options.shown & animated) : options.shown;

  std::vector<DopeSheetRow> rows(1);
  rows.front().kind = DopeSheetRow::Kind::Summary;
  rows.front().channels = visible;
  rows.front().keys = keysSetting(keys, visible);
  for (int g = static_cast<int>(FapGroup::VisemeExpression); g <= static_cast<int>(FapGroup::Tears);
       ++g) {
    const auto group = static_cast<FapGroup>(g);
    DopeSheetRow groupRow;
    groupRow.kind = DopeSheetRow::Kind::Group;
    groupRow.group = group;
    std::vector<DopeSheetRow> channelRows;
    for (const FapInfo& info : fapTable()) {
      if (info.group != group || !visible.test(channelIndex(info.number))) continue;
      groupRow.channels.set(channelIndex(info.number));
      if (options.folded.test(static_cast<std::size_t>(g))) continue;
      DopeSheetRow row;
      row.kind = DopeSheetRow::Kind::Channel;
      row.group = group;
      row.fap = info.number;
      row.channels.set(channelIndex(info.number));
      row.keys = keysSetting(keys, row.channels);
      channelRows.push_back(std::move(row));
    }
    if (groupRow.channels.none()) continue;
    groupRow.keys = keysSetting(keys, groupRow.channels);
    rows.push_back(std::move(groupRow));
    for (DopeSheetRow& row : channelRows) rows.push_back(std::move(row));
  }
  return rows;
}

std::vector<editing::ChannelKey> channelKeysOf(const DopeSheetRow& row, const Keyframe& key) {
  std::vector<editing::ChannelKey> out;
  const ChannelMask set = row.channels & key.channels;
  if (set.none()) return out;
  for (int i = 0; i < kChannelCount; ++i)
    if (set.test(static_cast<std::size_t>(i))) out.push_back({fapNumber(i), key.time});
  return out;
}

}  // namespace lacrima::editor
