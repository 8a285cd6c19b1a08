#pragma once
// A dense FAP animation: one value per channel per frame at a fixed frame rate.
// This is what a .fap file decodes to and what keyframes bake to.
#include <lacrima/common/FapChannels.h>

#include <string>
#include <vector>

namespace lacrima::inline common {

// FAP 1 in the grouped dialect: viseme_select1, viseme_select2, viseme_blend, viseme_def.
struct VisemeParams {
  int select1 = 0, select2 = 0, blend = 63;
  bool define = false;
  bool operator==(const VisemeParams&) const = default;
};

// FAP 2 in the grouped dialect: expression_select1, expression_intensity1,
// expression_select2, expression_intensity2, init_face, expression_def.
struct ExpressionParams {
  int select1 = 0, intensity1 = 0, select2 = 0, intensity2 = 0;
  bool initFace = false, define = false;
  bool operator==(const ExpressionParams&) const = default;
};

// High-level FAPs of one frame. The scalar dialect's single number lands in select1
// (blend 63, intensity 63); channel values 1 and 2 mirror select1 for plotting and CSV.
struct HighLevelFrame {
  VisemeParams viseme;
  ExpressionParams expression;
  bool operator==(const HighLevelFrame&) const = default;
};

struct FapAnimation {
  std::string name = "lacrima";   // header label; one token when written
  std::string version = "2.1";    // header version as read ("2.0", "2.1", ...)
  double fps = 22.0;              // frames per second, > 0
  std::vector<FapValues> frames;  // frame i plays at time i / fps

  // Channels that carry data (masked in some frame of a file, keyed in a document).
  // Writers mask at least these, so a round trip keeps them.
  ChannelMask animated;

  // Parallel to frames when channel 1 or 2 is animated; empty otherwise.
  std::vector<HighLevelFrame> highLevel;

  int frameCount() const { return static_cast<int>(frames.size()); }
  double duration() const { return frames.empty() ? 0.0 : (frameCount() - 1) / fps; }

  // Channels that are animated or non-zero in some frame.
  ChannelMask usedChannels() const;

  // True when a tear channel (69 or 70) is non-zero in some frame.
  bool hasTears() const;

  // Channel values at time t seconds, linearly interpolated between frames (tear channels
  // rounded), clamped to the first and last frame. Lets a player render faster than the file.
  FapValues sample(double seconds) const;
};

}  // namespace lacrima::inline common
