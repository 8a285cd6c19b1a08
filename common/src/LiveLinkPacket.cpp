#include <lacrima/common/Diagnostics.h>
#include <lacrima/common/LiveLinkPacket.h>

#include <cmath>
#include <cstring>

namespace lacrima::inline common {

namespace {

constexpr int kPacketVersion = 6;

// Reads big-endian fields, failing with the offset of the field that is not there.
class PacketReader {
 public:
  PacketReader(std::string_view bytes, const std::string& name) : bytes_(bytes), name_(name) {}

  std::uint32_t u8(const char* what) { return take(1, what)[0]; }
  std::uint32_t u32(const char* what) {
    const unsigned char* p = take(4, what);
    return std::uint32_t{p[0]} << 24 | std::uint32_t{p[1]} << 16 | std::uint32_t{p[2]} << 8 |
           std::uint32_t{p[3]};
  }
  float f32(const char* what) {
    const std::uint32_t bits = u32(what);
    float value = 0;
    std::memcpy(&value, &bits, sizeof value);
    return value;
  }
  std::string text(const char* what) {
    const std::size_t at = offset_;
    const std::uint32_t length = u32(what);
    if (length > LiveLinkPacket::kMaxNameLength) {
      fail(at, std::string(what) + " is " + std::to_string(length) +
                   " bytes long; expected at most " +
                   std::to_string(LiveLinkPacket::kMaxNameLength));
    }
    const unsigned char* p = take(length, what);
    return std::string(reinterpret_cast<const char*>(p), length);
  }
  std::size_t offset() const { return offset_; }
  std::size_t left() const { return bytes_.size() - offset_; }

  [[noreturn]] void fail(std::size_t at, const std::string& message) const {
    // The byte offset stands where a text file's column would (1-based).
    throw FileError({name_, 0, static_cast<int>(at) + 1},
                    "Live Link packet, byte " + std::to_string(at) + ": " + message);
  }

 private:
  const unsigned char* take(std::size_t n, const char* what) {
    if (left() < n) {
      fail(offset_, std::string("the packet ends (") + std::to_string(bytes_.size()) +
                        " bytes) where " + what + " was expected");
    }
    const auto* p = reinterpret_cast<const unsigned char*>(bytes_.data() + offset_);
    offset_ += n;
    return p;
  }

  std::string_view bytes_;
  const std::string& name_;
  std::size_t offset_ = 0;
};

}  // namespace

double LiveLinkPacket::frameRate() const {
  if (rateNumerator <= 0 || rateDenominator <= 0) return 0;
  const double rate = static_cast<double>(rateNumerator) / rateDenominator;
  return rate <= 1000 ? rate : 0;
}

const std::array<std::string_view, LiveLinkPacket::kValueCount>& liveLinkValueNames() {
  static const std::array<std::string_view, LiveLinkPacket::kValueCount> kNames = {
      "eyeBlinkLeft",
      "eyeLookDownLeft",
      "eyeLookInLeft",
      "eyeLookOutLeft",
      "eyeLookUpLeft",
      "eyeSquintLeft",
      "eyeWideLeft",
      "eyeBlinkRight",
      "eyeLookDownRight",
      "eyeLookInRight",
      "eyeLookOutRight",
      "eyeLookUpRight",
      "eyeSquintRight",
      "eyeWideRight",
      "jawForward",
      "jawLeft",
      "jawRight",
      "jawOpen",
      "mouthClose",
      "mouthFunnel",
      "mouthPucker",
      "mouthLeft",
      "mouthRight",
      "mouthSmileLeft",
      "mouthSmileRight",
      "mouthFrownLeft",
      "mouthFrownRight",
      "mouthDimpleLeft",
      "mouthDimpleRight",
      "mouthStretchLeft",
      "mouthStretchRight",
      "mouthRollLower",
      "mouthRollUpper",
      "mouthShrugLower",
      "mouthShrugUpper",
      "mouthPressLeft",
      "mouthPressRight",
      "mouthLowerDownLeft",
      "mouthLowerDownRight",
      "mouthUpperUpLeft",
      "mouthUpperUpRight",
      "browDownLeft",
      "browDownRight",
      "browInnerUp",
      "browOuterUpLeft",
      "browOuterUpRight",
      "cheekPuff",
      "cheekSquintLeft",
      "cheekSquintRight",
      "noseSneerLeft",
      "noseSneerRight",
      "tongueOut",
      "headYaw",
      "headPitch",
      "headRoll",
      "leftEyeYaw",
      "leftEyePitch",
      "leftEyeRoll",
      "rightEyeYaw",
      "rightEyePitch",
      "rightEyeRoll"};
  return kNames;
}

int liveLinkValueIndex(std::string_view name) {
  const auto& names = liveLinkValueNames();
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return static_cast<int>(i);
  return -1;
}

LiveLinkPacket decodeLiveLinkPacket(std::string_view bytes, const std::string& displayName) {
  PacketReader in(bytes, displayName);
  LiveLinkPacket packet;
  packet.version = static_cast<int>(in.u8("the packet version"));
  if (packet.version != kPacketVersion) {
    in.fail(0, "packet version " + std::to_string(packet.version) + "; expected " +
                   std::to_string(kPacketVersion) + " (Live Link Face)");
  }
  packet.deviceId = in.text("the device id");
  packet.subject = in.text("the subject name");
  packet.frameNumber = static_cast<std::int32_t>(in.u32("the frame number"));
  packet.subFrame = in.f32("the sub-frame");
  packet.rateNumerator = static_cast<std::int32_t>(in.u32("the rate numerator"));
  packet.rateDenominator = static_cast<std::int32_t>(in.u32("the rate denominator"));
  const std::size_t countAt = in.offset();
  const std::uint32_t count = in.u8("the value count");
  if (count != LiveLinkPacket::kValueCount) {
    in.fail(countAt, "value count " + std::to_string(count) + "; expected " +
                         std::to_string(LiveLinkPacket::kValueCount) +
                         " (52 blendshapes, head and eye angles)");
  }
  for (int i = 0; i < LiveLinkPacket::kValueCount; ++i) {
    const std::size_t at = in.offset();
    const float value = in.f32("a blendshape value");
    if (!std::isfinite(value)) {
      in.fail(at, std::string(liveLinkValueNames()[static_cast<std::size_t>(i)]) +
                      " is not a finite number");
    }
    packet.values[static_cast<std::size_t>(i)] = value;
  }
  if (in.left() != 0) {
    in.fail(in.offset(), std::to_string(in.left()) + " bytes after the last value; expected none");
  }
  return packet;
}

}  // namespace lacrima::inline common
