#include <lacrima/common/FapTable.h>

#include <array>
#include <stdexcept>
#include <string>
#include <utility>

namespace lacrima::inline common {
namespace {

// Head rotations edit over +-30 degrees (AU = 1e-5 rad). Greta's sliders stop at +-1860 AU,
// about one degree: too little for a nod or a sob.
constexpr int kHeadTurn = 52360;

// Positive motion as the standard states it. Kept symbolic so the table reads like the
// standard and so compile-time checks can tie it to FapMotion; converted to vectors once.
enum class Dir {
  Zero,       // not spatial
  Up,         // +y
  Down,       // -y
  Left,       // +x, the face's own left
  Right,      // -x
  Forward,    // +z
  YawLeft,    // rotation axis +y: R_y(+a) takes the gaze +z toward +x
  PitchDown,  // rotation axis +x: R_x(+a) takes the gaze +z toward -y
  RollRight,  // rotation axis +z: R_z(+a) takes the head top +y toward -x
};

struct Row {
  int number;
  std::string_view name;
  FapUnit unit;
  bool bidirectional;
  FapMotion motion;
  Dir dir;
  FapGroup group;
  std::string_view featurePoint;
  int quantizerStep;
  int sliderMin, sliderMax;
  std::string_view description;
};

using enum FapUnit;
using enum FapMotion;
using enum FapGroup;
using enum Dir;
constexpr bool B = true;   // bidirectional
constexpr bool U = false;  // unidirectional

// ISO/IEC 14496-2 Annex C facts (unit, U/B, direction, group, feature point, quantiser step)
// with Greta's editor ranges as slider hints; descriptions are Lacrima's own.
constexpr std::array<Row, kChannelCount> kRows{{
    // High-level values are codes, not distances: the sliders span the select codes.
    {1, "viseme", None, U, HighLevel, Zero, VisemeExpression, "", 1, 0, 14,
     "Selects and blends two mouth shapes used for speech sounds."},
    {2, "expression", None, U, HighLevel, Zero, VisemeExpression, "", 1, 0, 6,
     "Selects and mixes two of the six basic facial expressions."},
    {3, "open_jaw", MNS, U, Translation, Down, JawChinInnerLips, "2.1", 4, 0, 1080,
     "Drops the jaw; positive opens the mouth."},
    {4, "lower_t_midlip", MNS, B, Translation, Down, JawChinInnerLips, "2.2", 2, -600, 600,
     "Moves the centre of the upper lip's inner edge; positive lowers it."},
    {5, "raise_b_midlip", MNS, B, Translation, Up, JawChinInnerLips, "2.3", 2, -1860, 1860,
     "Moves the centre of the lower lip's inner edge; positive raises it."},
    {6, "stretch_l_cornerlip", MW, B, Translation, Left, JawChinInnerLips, "2.4", 2, -600, 600,
     "Pulls the left inner lip corner sideways; positive moves it out toward the face's left."},
    {7, "stretch_r_cornerlip", MW, B, Translation, Right, JawChinInnerLips, "2.5", 2, -600, 600,
     "Pulls the right inner lip corner sideways; positive moves it out toward the face's right."},
    {8, "lower_t_lip_lm", MNS, B, Translation, Down, JawChinInnerLips, "2.6", 2, -600, 600,
     "Moves the upper inner lip midway between its centre and left corner; positive lowers it."},
    {9, "lower_t_lip_rm", MNS, B, Translation, Down, JawChinInnerLips, "2.7", 2, -600, 600,
     "Moves the upper inner lip midway between its centre and right corner; positive lowers it."},
    {10, "raise_b_lip_lm", MNS, B, Translation, Up, JawChinInnerLips, "2.8", 2, -1860, 1860,
     "Moves the lower inner lip midway between its centre and left corner; positive raises it."},
    {11, "raise_b_lip_rm", MNS, B, Translation, Up, JawChinInnerLips, "2.9", 2, -1860, 1860,
     "Moves the lower inner lip midway between its centre and right corner; positive raises it."},
    {12, "raise_l_cornerlip", MNS, B, Translation, Up, JawChinInnerLips, "2.4", 2, -600, 600,
     "Moves the left inner lip corner vertically; positive raises it."},
    {13, "raise_r_cornerlip", MNS, B, Translation, Up, JawChinInnerLips, "2.5", 2, -600, 600,
     "Moves the right inner lip corner vertically; positive raises it."},
    {14, "thrust_jaw", MNS, U, Translation, Forward, JawChinInnerLips, "2.1", 1, 0, 600,
     "Pushes the jaw forward so the chin juts out."},
    {15, "shift_jaw", MW, B, Translation, Right, JawChinInnerLips, "2.1", 1, -1080, 1080,
     "Slides the jaw sideways; positive moves it toward the face's right."},
    {16, "push_b_lip", MNS, B, Translation, Forward, JawChinInnerLips, "2.3", 1, -1080, 1080,
     "Moves the middle of the lower lip in depth; positive pushes it out."},
    {17, "push_t_lip", MNS, B, Translation, Forward, JawChinInnerLips, "2.2", 1, -1080, 1080,
     "Moves the middle of the upper lip in depth; positive pushes it out."},
    {18, "depress_chin", MNS, B, Translation, Up, JawChinInnerLips, "2.10", 1, -420, 420,
     "Bunches the chin boss upward as in a pout; positive pushes it up."},
    {19, "close_t_l_eyelid", IRISD, B, Translation, Down, Eyes, "3.1", 1, -1080, 1080,
     "Moves the left upper eyelid; positive lowers it to shut the eye."},
    {20, "close_t_r_eyelid", IRISD, B, Translation, Down, Eyes, "3.2", 1, -1080, 1080,
     "Moves the right upper eyelid; positive lowers it to shut the eye."},
    {21, "close_b_l_eyelid", IRISD, B, Translation, Up, Eyes, "3.3", 1, -600, 600,
     "Moves the left lower eyelid; positive raises it to shut the eye."},
    {22, "close_b_r_eyelid", IRISD, B, Translation, Up, Eyes, "3.4", 1, -600, 600,
     "Moves the right lower eyelid; positive raises it to shut the eye."},
    {23, "yaw_l_eyeball", AU, B, Rotation, YawLeft, Eyes, "3.5", 128, -153600, 153600,
     "Turns the left eye sideways; positive looks toward the face's left."},
    {24, "yaw_r_eyeball", AU, B, Rotation, YawLeft, Eyes, "3.6", 128, -153600, 153600,
     "Turns the right eye sideways; positive looks toward the face's left."},
    {25, "pitch_l_eyeball", AU, B, Rotation, PitchDown, Eyes, "3.5", 128, -115200, 115200,
     "Turns the left eye vertically; positive looks down."},
    {26, "pitch_r_eyeball", AU, B, Rotation, PitchDown, Eyes, "3.6", 128, -115200, 115200,
     "Turns the right eye vertically; positive looks down."},
    {27, "thrust_l_eyeball", ES, B, Translation, Forward, Eyes, "3.5", 1, -600, 600,
     "Moves the left eyeball in depth; positive pushes it out of the socket."},
    {28, "thrust_r_eyeball", ES, B, Translation, Forward, Eyes, "3.6", 1, -600, 600,
     "Moves the right eyeball in depth; positive pushes it out of the socket."},
    // The standard gives pupils no editing range. The neutral pupil is a third of the iris
    // (~341 IRISD steps across), so -300..600 spans a pinpoint to nearly the whole iris.
    {29, "dilate_l_pupil", IRISD, B, Dilation, Zero, Eyes, "3.5", 1, -300, 600,
     "Resizes the left pupil; positive widens it."},
    {30, "dilate_r_pupil", IRISD, B, Dilation, Zero, Eyes, "3.6", 1, -300, 600,
     "Resizes the right pupil; positive widens it."},
    {31, "raise_l_i_eyebrow", ENS, B, Translation, Up, Eyebrows, "4.1", 2, -900, 900,
     "Moves the inner end of the left eyebrow; positive raises it."},
    {32, "raise_r_i_eyebrow", ENS, B, Translation, Up, Eyebrows, "4.2", 2, -900, 900,
     "Moves the inner end of the right eyebrow; positive raises it."},
    {33, "raise_l_m_eyebrow", ENS, B, Translation, Up, Eyebrows, "4.3", 2, -900, 900,
     "Moves the middle of the left eyebrow; positive raises it."},
    {34, "raise_r_m_eyebrow", ENS, B, Translation, Up, Eyebrows, "4.4", 2, -900, 900,
     "Moves the middle of the right eyebrow; positive raises it."},
    {35, "raise_l_o_eyebrow", ENS, B, Translation, Up, Eyebrows, "4.5", 2, -900, 900,
     "Moves the outer end of the left eyebrow; positive raises it."},
    {36, "raise_r_o_eyebrow", ENS, B, Translation, Up, Eyebrows, "4.6", 2, -900, 900,
     "Moves the outer end of the right eyebrow; positive raises it."},
    {37, "squeeze_l_eyebrow", ES, B, Translation, Right, Eyebrows, "4.1", 1, -900, 900,
     "Slides the left eyebrow sideways; positive draws it in toward the nose."},
    {38, "squeeze_r_eyebrow", ES, B, Translation, Left, Eyebrows, "4.2", 1, -900, 900,
     "Slides the right eyebrow sideways; positive draws it in toward the nose."},
    {39, "puff_l_cheek", ES, B, Translation, Left, Cheeks, "5.1", 2, -900, 900,
     "Bulges the left cheek sideways; positive puffs it outward."},
    {40, "puff_r_cheek", ES, B, Translation, Right, Cheeks, "5.2", 2, -900, 900,
     "Bulges the right cheek sideways; positive puffs it outward."},
    // 41, 42 and 47 are unidirectional in the standard, yet other editors (Greta) accept
    // negative values, so the slider keeps their symmetric range and files may hold them.
    {41, "lift_l_cheek", ENS, U, Translation, Up, Cheeks, "5.3", 2, -900, 900,
     "Lifts the left cheekbone area."},
    {42, "lift_r_cheek", ENS, U, Translation, Up, Cheeks, "5.4", 2, -900, 900,
     "Lifts the right cheekbone area."},
    {43, "shift_tongue_tip", MW, B, Translation, Right, Tongue, "6.1", 1, -1080, 1080,
     "Moves the tongue tip sideways; positive moves it toward the face's right."},
    {44, "raise_tongue_tip", MNS, B, Translation, Up, Tongue, "6.1", 1, -1080, 1080,
     "Moves the tongue tip vertically; positive raises it."},
    {45, "thrust_tongue_tip", MW, B, Translation, Forward, Tongue, "6.1", 1, -1080, 1080,
     "Moves the tongue tip in depth; positive pushes it forward."},
    {46, "raise_tongue", MNS, B, Translation, Up, Tongue, "6.2", 1, -1080, 1080,
     "Moves the body of the tongue vertically; positive raises it."},
    {47, "tongue_roll", AU, U, Curl, Zero, Tongue, "6.3;6.4", 512, -300, 300,
     "Curls both sides of the tongue upward into a trough."},
    {48, "head_pitch", AU, B, Rotation, PitchDown, Head, "7.1", 170, -kHeadTurn, kHeadTurn,
     "Nods the head about the top of the spine; positive tips the face down."},
    {49, "head_yaw", AU, B, Rotation, YawLeft, Head, "7.1", 170, -kHeadTurn, kHeadTurn,
     "Turns the head about the top of the spine; positive faces toward the face's left."},
    {50, "head_roll", AU, B, Rotation, RollRight, Head, "7.1", 170, -kHeadTurn, kHeadTurn,
     "Tilts the head about the top of the spine; positive leans its top to the face's right."},
    {51, "lower_t_midlip_o", MNS, B, Translation, Down, OuterLips, "8.1", 2, -600, 600,
     "Moves the centre of the upper lip's outer edge; positive lowers it."},
    {52, "raise_b_midlip_o", MNS, B, Translation, Up, OuterLips, "8.2", 2, -1860, 1860,
     "Moves the centre of the lower lip's outer edge; positive raises it."},
    {53, "stretch_l_cornerlip_o", MW, B, Translation, Left, OuterLips, "8.3", 2, -600, 600,
     "Pulls the left outer lip corner sideways; positive moves it out toward the face's left."},
    {54, "stretch_r_cornerlip_o", MW, B, Translation, Right, OuterLips, "8.4", 2, -600, 600,
     "Pulls the right outer lip corner sideways; positive moves it out toward the face's right."},
    {55, "lower_t_lip_lm_o", MNS, B, Translation, Down, OuterLips, "8.5", 2, -600, 600,
     "Moves the upper outer lip midway between its centre and left corner; positive lowers it."},
    {56, "lower_t_lip_rm_o", MNS, B, Translation, Down, OuterLips, "8.6", 2, -600, 600,
     "Moves the upper outer lip midway between its centre and right corner; positive lowers it."},
    {57, "raise_b_lip_lm_o", MNS, B, Translation, Up, OuterLips, "8.7", 2, -1860, 1860,
     "Moves the lower outer lip midway between its centre and left corner; positive raises it."},
    {58, "raise_b_lip_rm_o", MNS, B, Translation, Up, OuterLips, "8.8", 2, -1860, 1860,
     "Moves the lower outer lip midway between its centre and right corner; positive raises it."},
    {59, "raise_l_cornerlip_o", MNS, B, Translation, Up, OuterLips, "8.3", 2, -600, 600,
     "Moves the left outer lip corner vertically; positive raises it."},
    {60, "raise_r_cornerlip_o", MNS, B, Translation, Up, OuterLips, "8.4", 2, -600, 600,
     "Moves the right outer lip corner vertically; positive raises it."},
    {61, "stretch_l_nose", ENS, B, Translation, Left, Nose, "9.1", 1, -540, 540,
     "Moves the left nostril wing sideways; positive flares it outward."},
    {62, "stretch_r_nose", ENS, B, Translation, Right, Nose, "9.2", 1, -540, 540,
     "Moves the right nostril wing sideways; positive flares it outward."},
    {63, "raise_nose", ENS, B, Translation, Up, Nose, "9.3", 1, -680, 680,
     "Moves the tip of the nose vertically; positive raises it."},
    {64, "bend_nose", ENS, B, Translation, Right, Nose, "9.3", 1, -900, 900,
     "Bends the tip of the nose sideways; positive moves it toward the face's right."},
    {65, "raise_l_ear", ENS, B, Translation, Up, Ears, "10.1", 1, -900, 900,
     "Moves the left ear vertically; positive raises it."},
    {66, "raise_r_ear", ENS, B, Translation, Up, Ears, "10.2", 1, -900, 900,
     "Moves the right ear vertically; positive raises it."},
    {67, "pull_l_ear", ENS, B, Translation, Left, Ears, "10.3", 1, -900, 900,
     "Moves the left ear sideways; positive pulls it away from the head."},
    {68, "pull_r_ear", ENS, B, Translation, Right, Ears, "10.4", 1, -900, 900,
     "Moves the right ear sideways; positive pulls it away from the head."},
    // Lacrima's extension. The default tear source sits just below the lower-lid mid-point.
    {69, "tears_l_eye", Particles, U, TearCount, Zero, Tears, "3.3", 1, 0, 1000,
     "How many tear particles sit at the left eye's tear source in this frame."},
    {70, "tears_r_eye", Particles, U, TearCount, Zero, Tears, "3.4", 1, 0, 1000,
     "How many tear particles sit at the right eye's tear source in this frame."},
}};

constexpr bool isTranslationDir(Dir d) {
  return d == Up || d == Down || d == Left || d == Right || d == Forward;
}
constexpr bool isRotationDir(Dir d) { return d == YawLeft || d == PitchDown || d == RollRight; }

// Catch table typos at compile time rather than in a running editor.
constexpr bool rowsAreConsistent() {
  for (int i = 0; i < kChannelCount; ++i) {
    const Row& r = kRows[i];
    if (r.number != fapNumber(i) || r.name.empty() || r.description.empty()) return false;
    if ((r.motion == Translation) != isTranslationDir(r.dir)) return false;
    if ((r.motion == Rotation) != isRotationDir(r.dir)) return false;
    if (r.quantizerStep <= 0 || r.sliderMin >= r.sliderMax) return false;
    const bool toleratesNegative = r.number == 41 || r.number == 42 || r.number == 47;
    if (!r.bidirectional && r.sliderMin < 0 && !toleratesNegative) return false;
  }
  return true;
}
static_assert(rowsAreConsistent());

Eigen::Vector3f toVector(Dir d) {
  switch (d) {
    case Up:
      return {0, 1, 0};
    case Down:
      return {0, -1, 0};
    case Left:
      return {1, 0, 0};
    case Right:
      return {-1, 0, 0};
    case Forward:
      return {0, 0, 1};
    case YawLeft:
      return {0, 1, 0};
    case PitchDown:
      return {1, 0, 0};
    case RollRight:
      return {0, 0, 1};
    case Zero:
      break;
  }
  return Eigen::Vector3f::Zero();
}

// Eigen vectors are not constexpr, so the public table is built once from kRows; a
// function-local static also keeps it safe to use from other static initialisers.
const std::array<FapInfo, kChannelCount>& table() {
  static const std::array<FapInfo, kChannelCount> infos = [] {
    std::array<FapInfo, kChannelCount> out;
    for (int i = 0; i < kChannelCount; ++i) {
      const Row& r = kRows[i];
      out[i] = FapInfo{r.number,        r.name,          r.description,   r.unit,
                       r.bidirectional, r.motion,        toVector(r.dir), r.group,
                       r.featurePoint,  r.quantizerStep, r.sliderMin,     r.sliderMax};
    }
    return out;
  }();
  return infos;
}

constexpr std::array<std::pair<int, int>, 24> kMirrorPairs{{
    {6, 7},   {8, 9},   {10, 11}, {12, 13}, {19, 20}, {21, 22}, {23, 24}, {25, 26},
    {27, 28}, {29, 30}, {31, 32}, {33, 34}, {35, 36}, {37, 38}, {39, 40}, {41, 42},
    {53, 54}, {55, 56}, {57, 58}, {59, 60}, {61, 62}, {65, 66}, {67, 68}, {69, 70},
}};

constexpr std::array<int, kChannelCount> kMirror = [] {
  std::array<int, kChannelCount> m{};
  for (int i = 0; i < kChannelCount; ++i) m[i] = fapNumber(i);
  for (auto [l, r] : kMirrorPairs) {
    m[channelIndex(l)] = r;
    m[channelIndex(r)] = l;
  }
  return m;
}();

constexpr bool mirrorIsInvolution() {
  for (int i = 0; i < kChannelCount; ++i)
    if (kMirror[channelIndex(kMirror[i])] != fapNumber(i)) return false;
  return true;
}
static_assert(mirrorIsInvolution());

// Negate iff the mirror image (x -> -x) of this channel's positive motion is the opposite of
// the counterpart's positive motion. A translation d mirrors to (-dx, dy, dz); a rotation
// axis is a pseudo-vector, so it mirrors to (ax, -ay, -az): turning about y or z changes
// sense in the mirror. Hence: sideways centre FAPs (15, 43, 64), head yaw and roll (49, 50),
// and eyeball yaw (23, 24: both positive toward the face's left, so a mirrored gaze to the
// left is a gaze to the right). Pairs such as 6 left / 7 right or 37 right / 38 left are
// already mirror images and keep their sign; pitch (about x) keeps its sign too.
constexpr std::array<int, 7> kNegatedOnMirror{15, 23, 24, 43, 49, 50, 64};

int checkedIndex(int fap) {
  if (!isValidFap(fap))
    throw std::out_of_range("FAP channel " + std::to_string(fap) + " is not in 1.." +
                            std::to_string(kChannelCount));
  return channelIndex(fap);
}

}  // namespace

std::span<const FapInfo, kChannelCount> fapTable() { return table(); }

const FapInfo& fapInfo(int fap) { return table()[checkedIndex(fap)]; }

std::optional<int> fapByName(std::string_view name) {
  for (const Row& r : kRows)
    if (r.name == name) return r.number;
  return std::nullopt;
}

int mirroredFap(int fap) { return kMirror[checkedIndex(fap)]; }

bool mirrorNegates(int fap) {
  checkedIndex(fap);
  for (int n : kNegatedOnMirror)
    if (n == fap) return true;
  return false;
}

std::string_view toString(FapUnit unit) {
  switch (unit) {
    case None:
      return "none";
    case IRISD:
      return "IRISD";
    case ES:
      return "ES";
    case ENS:
      return "ENS";
    case MNS:
      return "MNS";
    case MW:
      return "MW";
    case AU:
      return "AU";
    case Particles:
      return "particles";
  }
  return "unknown";
}

std::string_view toString(FapGroup group) {
  switch (group) {
    case VisemeExpression:
      return "visemes and expressions";
    case JawChinInnerLips:
      return "jaw, chin and inner lips";
    case Eyes:
      return "eyes";
    case Eyebrows:
      return "eyebrows";
    case Cheeks:
      return "cheeks";
    case Tongue:
      return "tongue";
    case Head:
      return "head";
    case OuterLips:
      return "outer lips";
    case Nose:
      return "nose";
    case Ears:
      return "ears";
    case Tears:
      return "tears";
  }
  return "unknown";
}

}  // namespace lacrima::inline common
