#pragma once
// Edit planning for the graph editor: per channel and key shapes, handle drags and key drags,
// each returned as a KeyChange for EditorModel::editKeys (one undo step). Nothing here touches
// a model; the functions read the keys and say what they become.
//
// Handle rules (as in Blender's Graph Editor):
//   - Dragging an Auto handle makes the key Aligned; both handles start where the auto rule
//     put them, so the curve only changes where the drag moves it.
//   - Aligned: the opposite handle keeps its length and points the opposite way, so the
//     curve's tangent stays continuous through the key. Length is measured in the handle's own
//     units, sqrt(dt^2 + dv^2) (seconds, channel units), as Blender measures in frames and
//     values.
//   - Free: only the dragged handle moves.
//   - A handle acts on one segment: the out handle on the segment leaving the key, the in
//     handle on the one arriving (the previous key's segment). That segment becomes Bézier.
//   - An out handle never points back in time (dt >= 0), an in handle never forward.
#include <lacrima/editing/EditorModel.h>
#include <lacrima/editing/KeyChange.h>

#include <span>
#include <vector>

namespace lacrima::editing {

enum class HandleSide { In, Out };

// The interpolation of the selected channel keys' segments (the segment leaving each key).
KeyChange setChannelKeyShapes(const KeyframeSequence& keys, std::span<const ChannelKey> selected,
                              Interpolation interpolation);
// The handle type of the selected channel keys. Aligned and Free start from the handles the
// curve uses now (auto ones computed), so switching never moves the curve except that Aligned
// turns the in handle to line up with the out handle. Auto forgets stored handles.
KeyChange setChannelKeyShapes(const KeyframeSequence& keys, std::span<const ChannelKey> selected,
                              HandleType handles);

// Channel `fap`'s handle on `side` of its key at `time` set to `offset` (dt seconds, dv channel
// units, from the key), following the rules above. No-op for a key that does not set `fap` or
// an offset that is not finite.
KeyChange moveHandle(const KeyframeSequence& keys, int fap, double time, HandleSide side,
                     Handle offset);

// One channel key of a drag and the value it is to have.
struct ChannelKeyMove {
  ChannelKey key;
  double value = 0.0;
};

// The result of moving channel keys: the change and where the moved keys now are.
struct ChannelKeyMoveResult {
  KeyChange change;
  std::vector<ChannelKey> moved;
};

// Moves channel keys by whole `frames` at `fps` (keys on the frame grid stay on it, times stay
// >= 0) and gives each its new value, sanitised: finite, within the channel's edit limits,
// whole particles for tears and whole codes for FAPs 1/2, and whole numbers when
// `wholeValues`. A channel key landing on a key of its channel that does not move replaces it.
// Each moved channel takes its value and shape with it; a key left with no channels goes.
ChannelKeyMoveResult moveChannelKeys(const KeyframeSequence& keys,
                                     std::span<const ChannelKeyMove> moves, int frames, double fps,
                                     bool wholeValues);

// Single-key conveniences over moveChannelKeys.
KeyChange moveChannelKeyValue(const KeyframeSequence& keys, int fap, double time, double value,
                              bool wholeValues = false);
KeyChange moveChannelKeyTime(const KeyframeSequence& keys, int fap, double time, int frames,
                             double fps);

}  // namespace lacrima::editing
