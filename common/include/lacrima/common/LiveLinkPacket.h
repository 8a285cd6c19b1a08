#pragma once
// One UDP packet of Epic Games' Live Link Face app (port 11111 by default): the 52 ARKit
// blendshapes and the head and eye angles of one frame. The layout, as public decoders read it
// (docs/live.md cites them), all integers and floats big-endian:
//
//   uint8   packet version (6)
//   uint32  device id length, then its bytes
//   uint32  subject name length, then its bytes
//   int32   frame number, float sub-frame, int32 rate numerator, int32 rate denominator
//   uint8   value count (61)
//   float   x61: the 52 blendshapes (eyeBlinkLeft ... noseSneerRight, tongueOut), then head
//           yaw, pitch, roll, left eye yaw, pitch, roll, right eye yaw, pitch, roll
//
// Every length is checked against the bytes before anything is read or allocated.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace lacrima::inline common {

struct LiveLinkPacket {
  static constexpr int kValueCount = 61;
  static constexpr int kBlendshapeCount = 52;
  // Names are kept short in messages and memory: a real device id is a 36-character UUID.
  static constexpr std::size_t kMaxNameLength = 256;

  int version = 0;
  std::string deviceId;
  std::string subject;
  std::int32_t frameNumber = 0;
  float subFrame = 0;
  std::int32_t rateNumerator = 0;
  std::int32_t rateDenominator = 1;
  std::array<float, kValueCount> values{};

  // The frame rate the packet names, or 0 when it names none that makes sense.
  double frameRate() const;
};

// The names of the 61 values in packet order (ARKit's names, then headYaw ... rightEyeRoll).
const std::array<std::string_view, LiveLinkPacket::kValueCount>& liveLinkValueNames();
// Index of a value by name, or -1.
int liveLinkValueIndex(std::string_view name);

// Decodes one datagram. Throws FileError naming `displayName`, the byte offset (as the column)
// and what was expected: a short packet, an unknown version, a name longer than kMaxNameLength,
// a count other than 61, values that are not finite, bytes after the last value.
LiveLinkPacket decodeLiveLinkPacket(std::string_view bytes, const std::string& displayName);

}  // namespace lacrima::inline common
