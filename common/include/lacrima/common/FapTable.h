#pragma once
// The MPEG-4 FAP table (ISO/IEC 14496-2 Annex C) plus Lacrima's two tear channels.
//
// Face frame: +y up, +x the face's own left, +z forward (out of the face). A low-level FAP
// value v moves its feature point by v * FAPU along positiveMotion (translations), or turns
// by v * 1e-5 rad about positiveMotion by the right-hand rule (rotations).
#include <lacrima/common/FapChannels.h>

#include <Eigen/Core>
#include <optional>
#include <span>
#include <string_view>

namespace lacrima::inline common {

// The unit a channel's value counts in.
enum class FapUnit {
  None,       // high-level FAPs 1 and 2 (codes, not distances)
  IRISD,      // iris diameter / 1024
  ES,         // eye separation / 1024
  ENS,        // eye-nose separation / 1024
  MNS,        // mouth-nose separation / 1024
  MW,         // mouth width / 1024
  AU,         // angle unit, 1e-5 rad
  Particles,  // tear channels: a whole number of particles
};

// How a value moves the face.
enum class FapMotion {
  HighLevel,    // FAP 1 (viseme) and 2 (expression)
  Translation,  // feature point moves along positiveMotion
  Rotation,     // eyeball or head turns about positiveMotion (right-hand rule)
  Dilation,     // pupil grows (29, 30)
  Curl,         // tongue sides curl up (47)
  TearCount,    // 69, 70
};

// The standard's masking groups, plus Lacrima's group for the tear channels.
enum class FapGroup {
  VisemeExpression = 1,  // 1-2
  JawChinInnerLips = 2,  // 3-18
  Eyes = 3,              // 19-30
  Eyebrows = 4,          // 31-38
  Cheeks = 5,            // 39-42
  Tongue = 6,            // 43-47
  Head = 7,              // 48-50
  OuterLips = 8,         // 51-60
  Nose = 9,              // 61-64
  Ears = 10,             // 65-68
  Tears = 11,            // 69-70 (Lacrima extension)
};

struct FapInfo {
  int number;                    // 1..70
  std::string_view name;         // e.g. "open_jaw", "tears_l_eye"
  std::string_view description;  // one sentence, for tooltips
  FapUnit unit;
  bool bidirectional;  // false: only values >= 0 are meaningful
  FapMotion motion;
  Eigen::Vector3f positiveMotion;  // unit direction or rotation axis; zero when not spatial
  FapGroup group;
  std::string_view featurePoint;  // e.g. "2.1"; "6.3;6.4" for tongue_roll; "" for 1, 2
  int quantizerStep;              // binary-stream step; a sensible slider granularity
  int sliderMin, sliderMax;       // practical editing range (not normative limits)
};

// All 70 channels in number order: fapTable()[channelIndex(n)].number == n.
std::span<const FapInfo, kChannelCount> fapTable();

// The entry for channel `fap` (1..70); precondition isValidFap(fap).
const FapInfo& fapInfo(int fap);

// Channel number for a name ("open_jaw" -> 3), or nullopt.
std::optional<int> fapByName(std::string_view name);

// The left/right counterpart of a channel (6 <-> 7, 69 <-> 70), or the channel itself
// for centre FAPs such as open_jaw. Used for mirroring and symmetric editing.
int mirroredFap(int fap);

// Whether a value on this channel must be negated when mirrored onto mirroredFap(fap):
// true for sideways motions of centre FAPs (shift_jaw, bend_nose, head yaw/roll, ...).
bool mirrorNegates(int fap);

std::string_view toString(FapUnit unit);
std::string_view toString(FapGroup group);

}  // namespace lacrima::inline common
