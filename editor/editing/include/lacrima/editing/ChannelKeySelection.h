#pragma once
// The channel keys selected in the dope sheet and the graph editor. A small model of its own:
// the views select and read through it and follow its changed() signal; the document model
// keeps it true to the keys (an edit that removes a key drops it here), and key-edit commands
// restore it on undo and redo.
#include <lacrima/common/Keyframes.h>

#include <QObject>

#include <compare>
#include <vector>

namespace lacrima::editing {

// One channel's key: the key at `time` as far as channel `fap` is concerned. The dope sheet
// and the graph editor select these; the key rows (EditorModel::selectedTimes) select whole
// keys.
struct ChannelKey {
  int fap = 0;
  double time = 0.0;
  auto operator<=>(const ChannelKey&) const = default;
};

class ChannelKeySelection : public QObject {
  Q_OBJECT
 public:
  // `keys` are the document's, read (never written) to keep only channel keys that exist;
  // they must outlive this object.
  explicit ChannelKeySelection(const KeyframeSequence& keys, QObject* parent = nullptr);

  // Sorted, unique, each naming a key that sets its channel, at that key's exact time.
  const std::vector<ChannelKey>& keys() const { return selected_; }
  bool empty() const { return selected_.empty(); }
  // Keys that do not exist (or do not set their channel) are dropped; times within a key's
  // snapping distance name that key.
  void select(std::vector<ChannelKey> keys);
  void clear() { select({}); }
  bool contains(const ChannelKey& key) const;
  // Drops what the keys no longer hold (after an edit of the keys).
  void prune() { select(selected_); }

 signals:
  void changed();

 private:
  std::vector<ChannelKey> existing(std::vector<ChannelKey> keys) const;

  const KeyframeSequence& sequence_;
  std::vector<ChannelKey> selected_;
};

}  // namespace lacrima::editing
