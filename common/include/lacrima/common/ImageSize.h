#pragma once
// Image and window sizes: what the offscreen renderer accepts and what the tools read from a
// command line as "WxH" (lacrima-player --size, lacrima-editor --size, lacrima-bench player and
// editor --size).
#include <QSize>

#include <string>
#include <string_view>

namespace lacrima::inline common {

// One set of bounds for every size the tools accept. The largest is the largest offscreen
// render target the renderer asks OGRE for (FaceRenderer); below the smallest a face is a few
// pixels and tells nothing.
inline constexpr int kMinImageSide = 16;
inline constexpr int kMaxImageSide = 8192;

inline bool isImageSizeInBounds(QSize size) {
  return size.width() >= kMinImageSide && size.height() >= kMinImageSide &&
         size.width() <= kMaxImageSide && size.height() <= kMaxImageSide;
}

struct ParsedImageSize {
  QSize size;         // valid when error is empty
  std::string error;  // what was expected, to follow "--size: "
};

// "1280x720" (or "1280X720"), both sides whole numbers in [kMinImageSide, kMaxImageSide].
ParsedImageSize parseImageSize(std::string_view text);

}  // namespace lacrima::inline common
