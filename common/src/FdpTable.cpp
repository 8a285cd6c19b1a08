#include <lacrima/common/FdpTable.h>

#include <algorithm>
#include <array>
#include <utility>

namespace lacrima::inline common {
namespace {

constexpr FdpSide C = FdpSide::Centre, L = FdpSide::Left, R = FdpSide::Right;

constexpr std::array<FdpInfo, 84> kPoints{{
    // 2: jaw, chin, inner lips
    {"2.1", 2, C, "Bottom of the chin on the mid line"},
    {"2.2", 2, C, "Middle of the upper lip's inner edge (where the lips meet)"},
    {"2.3", 2, C, "Middle of the lower lip's inner edge (where the lips meet)"},
    {"2.4", 2, L, "Left corner of the inner lip line"},
    {"2.5", 2, R, "Right corner of the inner lip line"},
    {"2.6", 2, L, "Upper lip's inner edge, halfway from its middle (2.2) to the left corner (2.4)"},
    {"2.7", 2, R,
     "Upper lip's inner edge, halfway from its middle (2.2) to the right corner (2.5)"},
    {"2.8", 2, L, "Lower lip's inner edge, halfway from its middle (2.3) to the left corner (2.4)"},
    {"2.9", 2, R,
     "Lower lip's inner edge, halfway from its middle (2.3) to the right corner (2.5)"},
    {"2.10", 2, C, "Chin boss: the most forward bulge of the chin, above its bottom (2.1)"},
    {"2.11", 2, L, "Left end of the chin's front"},
    {"2.12", 2, R, "Right end of the chin's front"},
    {"2.13", 2, L, "Left jaw angle, where the jaw line turns up towards the ear"},
    {"2.14", 2, R, "Right jaw angle, where the jaw line turns up towards the ear"},
    // 3: eyes
    {"3.1", 3, L, "Left upper eyelid's rim, at its middle"},
    {"3.2", 3, R, "Right upper eyelid's rim, at its middle"},
    {"3.3", 3, L, "Left lower eyelid's rim, at its middle"},
    {"3.4", 3, R, "Right lower eyelid's rim, at its middle"},
    {"3.5", 3, L, "Centre of the left pupil (the eyeball's centre for rigging)"},
    {"3.6", 3, R, "Centre of the right pupil (the eyeball's centre for rigging)"},
    {"3.7", 3, L, "Outer corner of the left eye"},
    {"3.8", 3, R, "Inner corner of the right eye (next to the nose)"},
    {"3.9", 3, L, "Left lower eyelid, middle of its outer crease below the rim"},
    {"3.10", 3, R, "Right lower eyelid, middle of its outer crease below the rim"},
    {"3.11", 3, L, "Inner corner of the left eye (next to the nose)"},
    {"3.12", 3, R, "Outer corner of the right eye"},
    {"3.13", 3, L, "Left upper eyelid, middle of its fold above the rim"},
    {"3.14", 3, R, "Right upper eyelid, middle of its fold above the rim"},
    // 4: eyebrows
    {"4.1", 4, L, "Inner end of the left eyebrow (towards the nose)"},
    {"4.2", 4, R, "Inner end of the right eyebrow (towards the nose)"},
    {"4.3", 4, L, "Top of the left eyebrow's arch"},
    {"4.4", 4, R, "Top of the right eyebrow's arch"},
    {"4.5", 4, L, "Outer end of the left eyebrow"},
    {"4.6", 4, R, "Outer end of the right eyebrow"},
    // 5: cheeks
    {"5.1", 5, L, "Middle of the left cheek"},
    {"5.2", 5, R, "Middle of the right cheek"},
    {"5.3", 5, L, "Left cheekbone, its most prominent point"},
    {"5.4", 5, R, "Right cheekbone, its most prominent point"},
    // 6: tongue
    {"6.1", 6, C, "Tip of the tongue"},
    {"6.2", 6, C, "Middle of the tongue's upper surface"},
    {"6.3", 6, L, "Left edge of the tongue"},
    {"6.4", 6, R, "Right edge of the tongue"},
    // 7: head
    {"7.1", 7, C, "Top of the neck's spine: the pivot the head turns about"},
    // 8: outer lips
    {"8.1", 8, C, "Middle of the upper lip's outer edge (the top of the red lip)"},
    {"8.2", 8, C, "Middle of the lower lip's outer edge (the bottom of the red lip)"},
    {"8.3", 8, L, "Left corner of the mouth (outer lip line)"},
    {"8.4", 8, R, "Right corner of the mouth (outer lip line)"},
    {"8.5", 8, L, "Upper lip's outer edge, halfway from the left corner (8.3) to its middle (8.1)"},
    {"8.6", 8, R,
     "Upper lip's outer edge, halfway from the right corner (8.4) to its middle (8.1)"},
    {"8.7", 8, L, "Lower lip's outer edge, halfway from the left corner (8.3) to its middle (8.2)"},
    {"8.8", 8, R,
     "Lower lip's outer edge, halfway from the right corner (8.4) to its middle (8.2)"},
    {"8.9", 8, R, "Right peak of the upper lip's bow"},
    {"8.10", 8, L, "Left peak of the upper lip's bow"},
    // 9: nose and teeth
    {"9.1", 9, L, "Outer edge of the left nostril's wing"},
    {"9.2", 9, R, "Outer edge of the right nostril's wing"},
    {"9.3", 9, C, "Tip of the nose"},
    {"9.4", 9, R, "Right edge of the nose's underside"},
    {"9.5", 9, L, "Left edge of the nose's underside"},
    {"9.6", 9, R, "Right side of the nose bone's upper end"},
    {"9.7", 9, L, "Left side of the nose bone's upper end"},
    {"9.8", 9, C, "Top edge of the upper front teeth (at the gum)"},
    {"9.9", 9, C, "Bottom edge of the lower front teeth (at the gum)"},
    {"9.10", 9, C, "Biting edge of the upper front teeth"},
    {"9.11", 9, C, "Biting edge of the lower front teeth"},
    {"9.12", 9, C, "Bump of the nose bridge on the mid line, where bone gives way to cartilage"},
    {"9.13", 9, L, "Left side of the nose bone's lower end"},
    {"9.14", 9, R, "Right side of the nose bone's lower end"},
    {"9.15", 9, C, "Base of the nose on the mid line, just above the upper lip"},
    // 10: ears
    {"10.1", 10, L, "Top of the left ear"},
    {"10.2", 10, R, "Top of the right ear"},
    {"10.3", 10, L, "Rearmost point of the left ear"},
    {"10.4", 10, R, "Rearmost point of the right ear"},
    {"10.5", 10, L, "Bottom of the left ear lobe"},
    {"10.6", 10, R, "Bottom of the right ear lobe"},
    {"10.7", 10, L, "Where the left ear lobe's lower edge meets the cheek"},
    {"10.8", 10, R, "Where the right ear lobe's lower edge meets the cheek"},
    {"10.9", 10, L, "Where the left ear's upper edge meets the side of the head"},
    {"10.10", 10, R, "Where the right ear's upper edge meets the side of the head"},
    // 11: hairline and skull
    {"11.1", 11, C, "Middle of the hairline above the forehead"},
    {"11.2", 11, R, "Right end of the hairline"},
    {"11.3", 11, L, "Left end of the hairline"},
    {"11.4", 11, C, "Top of the skull"},
    {"11.5", 11, C, "Top of the hair above the skull's top (11.4): the hair's thickness"},
    {"11.6", 11, C, "Back of the skull on the mid line"},
}};

// Left point, right point.
constexpr std::array<std::pair<std::string_view, std::string_view>, 32> kMirrors{{
    {"2.4", "2.5"},    {"2.6", "2.7"},   {"2.8", "2.9"},   {"2.11", "2.12"}, {"2.13", "2.14"},
    {"3.1", "3.2"},    {"3.3", "3.4"},   {"3.5", "3.6"},   {"3.7", "3.12"},  {"3.11", "3.8"},
    {"3.9", "3.10"},   {"3.13", "3.14"}, {"4.1", "4.2"},   {"4.3", "4.4"},   {"4.5", "4.6"},
    {"5.1", "5.2"},    {"5.3", "5.4"},   {"6.3", "6.4"},   {"8.3", "8.4"},   {"8.5", "8.6"},
    {"8.7", "8.8"},    {"8.10", "8.9"},  {"9.1", "9.2"},   {"9.5", "9.4"},   {"9.7", "9.6"},
    {"9.13", "9.14"},  {"10.1", "10.2"}, {"10.3", "10.4"}, {"10.5", "10.6"}, {"10.7", "10.8"},
    {"10.9", "10.10"}, {"11.3", "11.2"},
}};

}  // namespace

std::span<const FdpInfo> fdpTable() { return kPoints; }

std::span<const std::pair<std::string_view, std::string_view>> fdpMirrorPairs() { return kMirrors; }

std::optional<FdpInfo> fdpInfo(std::string_view id) {
  const auto found =
      std::find_if(kPoints.begin(), kPoints.end(), [&](const FdpInfo& p) { return p.id == id; });
  if (found == kPoints.end()) return std::nullopt;
  return *found;
}

std::string_view fdpDescription(std::string_view id) {
  const auto info = fdpInfo(id);
  return info ? info->description : std::string_view();
}

std::string_view fdpGroupName(int group) {
  switch (group) {
    case 2:
      return "jaw, chin and inner lips";
    case 3:
      return "eyes";
    case 4:
      return "eyebrows";
    case 5:
      return "cheeks";
    case 6:
      return "tongue";
    case 7:
      return "head";
    case 8:
      return "outer lips";
    case 9:
      return "nose and teeth";
    case 10:
      return "ears";
    case 11:
      return "hairline and skull";
    default:
      return "";
  }
}

std::optional<std::string_view> mirroredFdp(std::string_view id) {
  const auto info = fdpInfo(id);
  if (!info) return std::nullopt;
  for (const auto& [left, right] : kMirrors) {
    if (left == id) return right;
    if (right == id) return left;
  }
  return info->id;
}

}  // namespace lacrima::inline common
