#pragma once
// One edit of a key sequence, stored so that undo and redo restore it exactly.
//
// Every keyframe edit (slider drag, add, delete, move, paste, interpolation, preset, mirror)
// reduces to "these keys are replaced by those keys". A KeyChange records the affected times
// T (the union of the times removed and the times written) with the keys found at T before the
// edit and the keys at T after it:
//
//   redo: remove every key at a time in T, insert `after`
//   undo: remove every key at a time in T, insert `before`
//
// Because both lists hold every key at every affected time, neither direction depends on the
// merge rule of KeyframeSequence::insert, and undo gives back a sequence that compares equal
// to the one before the edit (same times, modes, channels and values). Storage is proportional
// to the keys touched, not to the document, so slider drags on a long imported animation stay
// cheap.
#include <lacrima/common/Keyframes.h>

#include <span>
#include <vector>

namespace lacrima::editing {

// Two times closer than this name the same key (as KeyframeSequence::insert decides).
inline constexpr double kSameKeyTime = 1e-9;

// Index of the key at `seconds`, or -1. O(log n).
int findKey(const KeyframeSequence& keys, double seconds);

struct KeyChange {
  std::vector<double> times;     // affected times, ascending, unique
  std::vector<Keyframe> before;  // keys at `times` before the edit, ascending
  std::vector<Keyframe> after;   // keys at `times` after the edit, ascending

  bool isNoOp() const;  // before and after are the same keys
};

// The change "remove the keys at `removeTimes`, then write `written` (each replacing whatever
// key is left at its time)". A written key with no channels removes the key at its time.
KeyChange planReplace(const KeyframeSequence& keys, std::span<const double> removeTimes,
                      std::span<const Keyframe> written);

// Applies one side of a change: removes every key at change.times, inserts `side`.
void applyKeys(KeyframeSequence& keys, std::span<const double> times,
               std::span<const Keyframe> side);

}  // namespace lacrima::editing
