#pragma once
// The 70 animation channels of Lacrima: the 68 MPEG-4 FAPs plus two tear channels.
//
// Channels are numbered like FAPs, 1-based: 1 = viseme ... 68 = pull_r_ear,
// 69 = tears of the left eye, 70 = tears of the right eye. Arrays indexed by channel
// use index (fap - 1); channelIndex() and fapNumber() convert so that call sites read well.
#include <array>
#include <bitset>

namespace lacrima::inline common {

inline constexpr int kFapCount = 68;      // standard FAPs 1..68
inline constexpr int kChannelCount = 70;  // plus the two tear channels
inline constexpr int kTearLeftFap = 69;   // particles present at the left eye's source
inline constexpr int kTearRightFap = 70;  // particles present at the right eye's source

// Upper bound on a tear channel value. A tear count drives a particle allocation, so it is
// capped where it is read rather than trusted: 100k particles is ~10x what runs in real time.
inline constexpr int kMaxTearParticles = 100000;

constexpr bool isValidFap(int fap) { return fap >= 1 && fap <= kChannelCount; }
constexpr bool isTearChannel(int fap) { return fap == kTearLeftFap || fap == kTearRightFap; }
constexpr bool isHighLevelFap(int fap) { return fap == 1 || fap == 2; }
constexpr int channelIndex(int fap) { return fap - 1; }
constexpr int fapNumber(int index) { return index + 1; }

// One value per channel (masked-off channels hold 0, the neutral face). Values are FAPU
// counts; tear channels hold whole particle counts. float is exact for every integer a FAP
// file can sensibly hold (|v| < 2^24) and halves the memory of long animations.
using FapValues = std::array<float, kChannelCount>;

// Which channels a frame, key or animation uses; bit channelIndex(fap).
using ChannelMask = std::bitset<kChannelCount>;

}  // namespace lacrima::inline common
