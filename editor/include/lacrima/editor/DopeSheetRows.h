#pragma once
// The rows of the dope sheet, without widgets: a summary row over everything shown, then per
// FAP group a row summarising the group's channels, followed (unless the group is folded) by
// a row per channel. Groups come in the slider panel's order (FapGroup order).
//
// A row stands for a set of channels; its marks are the keys that set any of them, and a mark
// stands for those channels' keys at its time. So a group row's mark selects all its
// channels' keys at that time, and the summary row's mark every shown channel's key there.
#include <lacrima/common/FapTable.h>
#include <lacrima/common/Keyframes.h>
#include <lacrima/editing/EditorModel.h>

#include <bitset>
#include <vector>

namespace lacrima::editor {

struct DopeSheetRow {
  enum class Kind { Summary, Group, Channel };
  Kind kind = Kind::Summary;
  FapGroup group = FapGroup::VisemeExpression;  // Group and Channel rows
  int fap = 0;                                  // Channel rows
  ChannelMask channels;                         // the channels the row stands for
  std::vector<int> keys;  // indices of the keys setting any of `channels`, ascending
};

// Groups by FapGroup value (bit 1..11).
using GroupSet = std::bitset<12>;

struct DopeSheetRowOptions {
  ChannelMask shown;         // channels passing the filter
  bool onlyAnimated = true;  // hide channels no key sets
  GroupSet folded;           // groups whose channel rows are hidden
};

// The rows for `keys` (summary first; groups without a shown channel are left out).
std::vector<DopeSheetRow> buildDopeSheetRows(const KeyframeSequence& keys,
                                             const DopeSheetRowOptions& options);

// The channel keys a row's mark on `key` stands for (empty when the key sets none).
std::vector<editing::ChannelKey> channelKeysOf(const DopeSheetRow& row, const Keyframe& key);

}  // namespace lacrima::editor
