#pragma once
// The editor's Generate...: a take of the crying generator (docs/mood.md) written as keys over a
// time range of the document, reduced, in one undoable step (EditorModel::generateMood).
//
// The take starts at `start` (the script's time 0 is `start`) and runs to `end`. With `curves`
// (the project's mood curves, MoodCurves.h) the moods of each frame are the curves at that
// frame's document time instead, so a keyed ramp becomes a growing cry. Its frames at
// `fps` are thinned by reduceKeyFrames (KeyReduction.h) to within `tolerance` channel units,
// and each kept frame becomes a linear key at start + frame / fps holding the channels the take
// moves. Within [start, end] those channels lose their old keys; every other channel keeps its
// keys there, and a generated key at the time of an old one joins it. Keys outside the range stay
// as they are (a curve that crosses an edge of the range now runs into or out of the take). The
// colours are not keyed here (the project keeps its computed or keyed ones). The edit is one
// undo step: EditorModel::editKeys(plan.change, ...).
#include <lacrima/common/mood/MoodCurves.h>
#include <lacrima/common/mood/MoodScript.h>
#include <lacrima/editing/KeyChange.h>

#include <cstdint>

namespace lacrima::editing {

struct MoodGenerationRequest {
  double start = 0, end = 10;          // seconds of the document, start < end
  MoodScript script;                   // its time 0 at `start`
  const MoodCurves* curves = nullptr;  // when set, the moods instead: read at document time
  std::uint64_t seed = 1;
  double fps = 22;
  double tolerance = 1;  // key reduction, channel units (the import's default)
  // Add the take onto the keys' values at each frame (addMoodFrame, MoodLayer.h) instead of
  // replacing them: how a mood layer is baked (EditorModel::bakeMoodLayer) without changing
  // what the face shows.
  bool addToKeys = false;
};

struct MoodGenerationPlan {
  KeyChange change;
  int frames = 0;  // generated
  int keys = 0;    // kept after reduction
  ChannelMask channels;
};

// Throws std::invalid_argument for a range outside [0, 86400] or not increasing, a frame rate
// outside (0, 1000] or too many frames (kMaxBakedFrames), before generating anything.
MoodGenerationPlan planMoodGeneration(const KeyframeSequence& keys,
                                      const MoodGenerationRequest& request);

}  // namespace lacrima::editing
