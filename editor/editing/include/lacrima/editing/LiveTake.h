#pragma once
// A live performance recorded in the editor (Record, with a count-in) turned into keys: the take
// is a dense animation (LiveRecorder's frames at its rate); on the chosen channels it becomes
// keys from the playhead on, thinned by the key reduction of imports (KeyReduction.h) at the
// given tolerance, so every recorded frame is reproduced within it on every chosen channel.
//
// Within the take's span [start, start + duration], the chosen channels' existing keys are
// replaced: each key there loses those channels (and disappears if it has none left), and the
// take's kept frames write them, into the key at that time when there is one (its other channels
// stay) or into a new key with the document's default interpolation. Keys outside the span and
// the other channels are untouched. The result is one KeyChange: one undo step.
#include <lacrima/common/FapAnimation.h>
#include <lacrima/editing/KeyChange.h>

namespace lacrima::editing {

struct LiveTakeKeys {
  KeyChange change;
  int framesRecorded = 0;
  int keysWritten = 0;
  double maxError = 0;  // the reduction's largest error on the chosen channels
};

// `channels`: those to key (high-level codes and channels the take never set are ignored).
LiveTakeKeys planLiveTakeKeys(const KeyframeSequence& keys, const FapAnimation& take, double start,
                              const ChannelMask& channels, double tolerance,
                              Interpolation interpolation);

}  // namespace lacrima::editing
