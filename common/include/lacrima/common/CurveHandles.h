#pragma once
// The Bézier handles a channel's curve actually uses at one of its keys, for views that draw
// them (the graph editor) and edits that start from them (dragging an auto handle).
//
// Stored handles (Aligned, Free) are returned as stored. Auto handles store nothing; they are
// computed as KeyframeSequence::evaluate computes them: a third of the adjacent segment along
// the Smooth (Steffen) slope m at the key,
//   in  = (-h_in / 3, -m h_in / 3),   out = (h_out / 3, m h_out / 3),
// h_in, h_out = the durations of the channel's segments arriving at and leaving the key.
// Both functions use the very slope code of Keyframes.cpp, so a drawn auto handle is where the
// curve's tangent is.
#include <lacrima/common/Keyframes.h>

namespace lacrima::inline common {

struct EffectiveHandles {
  Handle in, out;
  bool hasIn = false;   // the channel has a key before this one (a segment arrives)
  bool hasOut = false;  // ... and after it (a segment leaves)
};

// Handles of channel `fap` at keys()[keyIndex]. Throws std::out_of_range when there is no such
// key or it does not set `fap`. Looks at no more than two of the channel's keys to either side.
EffectiveHandles effectiveHandles(const KeyframeSequence& keys, int fap, int keyIndex);

// The Smooth (Steffen) slope of channel `fap` at keys()[keyIndex], in channel units per second
// (0 for a channel with one key). Same preconditions as effectiveHandles.
double smoothSlope(const KeyframeSequence& keys, int fap, int keyIndex);

}  // namespace lacrima::inline common
