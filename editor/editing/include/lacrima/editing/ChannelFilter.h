#pragma once
// The slider filter: which channels a filter text selects.
//
// Alternatives are separated by commas; a channel matches when it matches any alternative.
// Within an alternative every word must match (AND). A word is
//   - a number "31": that channel;  a range "19-22": those channels;
//   - "left" / "right": the face's left or right channels (name contains _l_ / _r_ or ends
//     in _l / _r, as the standard names them);
//   - any other text: part of the channel's name (case-insensitive, '_' and ' ' alike); text
//     that is part of no channel name is looked up in the group names and the channels'
//     descriptions instead, so "jaw" finds open_jaw, thrust_jaw and shift_jaw, "eyes",
//     "cheeks" or "outer lips" find a group, and "inner brow" the inner eyebrows (31, 32).
// An empty filter matches everything.
#include <lacrima/common/FapTable.h>

#include <string>
#include <string_view>
#include <vector>

namespace lacrima::editing {

class ChannelFilter {
 public:
  explicit ChannelFilter(std::string_view text = {});

  bool isEmpty() const { return alternatives_.empty(); }
  bool matches(const FapInfo& info) const;
  ChannelMask matching() const;  // over the whole table

 private:
  struct Word {
    int from = 0, to = -1;  // number range when from <= to
    std::string text;       // lower case, '_' for spaces
    bool groups = false;    // no channel name contains `text`: match group names
  };
  std::vector<std::vector<Word>> alternatives_;
};

}  // namespace lacrima::editing
