#include <lacrima/editing/ChannelKeySelection.h>

#include <lacrima/common/FapChannels.h>
#include <lacrima/editing/KeyChange.h>

#include <algorithm>

namespace lacrima::editing {

ChannelKeySelection::ChannelKeySelection(const KeyframeSequence& keys, QObject* parent)
    : QObject(parent), sequence_(keys) {}

std::vector<ChannelKey> ChannelKeySelection::existing(std::vector<ChannelKey> keys) const {
  std::vector<ChannelKey> valid;
  for (const ChannelKey& key : keys) {
    if (!isValidFap(key.fap)) continue;
    const int index = findKey(sequence_, key.time);
    if (index < 0) continue;
    const Keyframe& found = sequence_.keys()[static_cast<std::size_t>(index)];
    if (found.has(key.fap)) valid.push_back({key.fap, found.time});
  }
  std::sort(valid.begin(), valid.end());
  valid.erase(std::unique(valid.begin(), valid.end()), valid.end());
  return valid;
}

void ChannelKeySelection::select(std::vector<ChannelKey> keys) {
  std::vector<ChannelKey> valid = existing(std::move(keys));
  if (valid == selected_) return;
  selected_ = std::move(valid);
  emit changed();
}

bool ChannelKeySelection::contains(const ChannelKey& key) const {
  const int index = findKey(sequence_, key.time);
  if (index < 0) return false;
  const ChannelKey exact{key.fap, sequence_.keys()[static_cast<std::size_t>(index)].time};
  return std::binary_search(selected_.begin(), selected_.end(), exact);
}

}  // namespace lacrima::editing
