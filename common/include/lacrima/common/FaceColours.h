#pragma once
// The face's colours beside its shape: the redness of the skin around the eyes and of the
// sclera, and the blush of the cheeks, each 0..1 (docs/decisions/0019-face-colours-as-curves.md).
// The player draws them as it always has (playback's OverlayWeights); these are values an
// animation sets over time instead of computing them.
namespace lacrima::inline common {

struct FaceColours {
  double redness = 0;
  double blush = 0;
  bool operator==(const FaceColours&) const = default;
};

}  // namespace lacrima::inline common
