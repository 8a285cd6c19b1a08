#pragma once
// The face's colours beside its shape: the redness of the skin around the eyes and of the
// sclera, and the blush of the cheeks, each 0..1. A project may key them as curves of their own
// (docs/decisions/0019-face-colours-as-project-curves.md); the player computes them otherwise
// (the redness from the animation's progress or the tears shed, the blush from the redness). A
// .fap file carries no colours, so a strict export stays standard.
#include <lacrima/common/IntensityCurve.h>

#include <optional>

namespace lacrima::inline common {

struct FaceColours {
  double redness = 0;
  double blush = 0;
  bool operator==(const FaceColours&) const = default;
};

// The colours an animation keys at one moment; absent ones are left to the player.
struct KeyedColours {
  std::optional<double> redness, blush;  // in [0, 1]
  bool operator==(const KeyedColours&) const = default;
};

// A project's keyed colours. A curve with keys replaces the computed value of its colour;
// values are clamped to [0, 1] where they are read.
struct FaceColourCurves {
  IntensityCurve redness;
  IntensityCurve blush;

  bool empty() const { return redness.empty() && blush.empty(); }
  // Each curve with keys, at `seconds`, clamped to [0, 1] (not a number: 0).
  KeyedColours at(double seconds) const;
  bool operator==(const FaceColourCurves&) const = default;
};

}  // namespace lacrima::inline common
