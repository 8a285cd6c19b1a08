#pragma once
// Edits of single channels' keys, as the dope sheet makes them: move, delete, copy, paste.
//
// A key (Keyframe) sets several channels at one time; a channel key is one channel of one key
// (ChannelKey {fap, time}). These functions plan an edit of some channel keys and leave every
// other channel of the same keys where it is:
//
//   - moving channel 3's key out of a key at 1 s that also sets channels 4 and 69 leaves a
//     key at 1 s with 4 and 69, and writes channel 3 (value and shape) into the key at the new
//     time, creating that key when there is none (it then takes the source key's default
//     interpolation);
//   - a channel key dropped on a time where its channel is keyed (and does not move) replaces
//     that channel key; the other channels of the key there are kept;
//   - a key left with no channel disappears.
//
// Every function returns the planned KeyChange (apply with EditorModel::editKeys, one undo
// step) and the channel keys where the edited ones are afterwards, for the selection.
#include <lacrima/editing/EditorModel.h>

#include <span>
#include <vector>

namespace lacrima::editing {

struct ChannelKeyEdit {
  KeyChange change;
  std::vector<ChannelKey> selection;  // the edited channel keys after the edit, sorted
};

// Copied channel keys: keys holding only the copied channels (value and shape), with times
// relative to the earliest copied channel key (so the first is at 0 s).
struct ChannelKeyClip {
  std::vector<Keyframe> keys;
  bool empty() const { return keys.empty(); }
  std::size_t channelKeyCount() const;
};

// Moves the selected channel keys by `frames` frames of 1 / fps. Keys on the frame grid stay
// exactly on it, off-grid keys keep their offset. The block stops at 0 s: moving earlier than
// the earliest selected key allows moves by what is left. Unknown channel keys are ignored.
ChannelKeyEdit moveChannelKeys(const KeyframeSequence& keys, std::span<const ChannelKey> selection,
                               int frames, double fps);

// Removes the selected channel keys from their keys (keys left empty are removed).
ChannelKeyEdit deleteChannelKeys(const KeyframeSequence& keys,
                                 std::span<const ChannelKey> selection);

// The selected channel keys as a clip (empty when none of them exists).
ChannelKeyClip copyChannelKeys(const KeyframeSequence& keys, std::span<const ChannelKey> selection);

// Writes the clip's channel keys onto the same channels, its first time at `at` seconds.
// Times are snapped like the playhead: to a key within half a frame, else to the frame grid;
// two clip keys landing on one frame: the later one wins.
ChannelKeyEdit pasteChannelKeys(const KeyframeSequence& keys, const ChannelKeyClip& clip, double at,
                                double fps);

}  // namespace lacrima::editing
