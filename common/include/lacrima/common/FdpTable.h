#pragma once
// The MPEG-4 feature points (ISO/IEC 14496-2 Annex C, facial definition parameters): where each
// of the 84 points 2.1 ... 11.6 sits on a face, in one sentence, for the people placing them
// (the Head workspace's reference panel, tooltips, checks). Left and right are the face's own
// (its left is +x in the face frame, FapTable.h). FapInfo::featurePoint names which FAP moves
// which of these points.
#include <optional>
#include <span>
#include <string_view>
#include <utility>

namespace lacrima::inline common {

enum class FdpSide { Centre, Left, Right };

struct FdpInfo {
  std::string_view id;  // "3.7"
  int group;            // 2..11, the part before the dot
  FdpSide side;
  std::string_view description;  // e.g. "Outer corner of the left eye"
};

// All 84 points, in group then index order (2.1, 2.2, ..., 2.14, 3.1, ...).
std::span<const FdpInfo> fdpTable();

// The entry for `id`, or nullopt for an id the standard does not define.
std::optional<FdpInfo> fdpInfo(std::string_view id);

// The description of `id` ("" for an unknown id).
std::string_view fdpDescription(std::string_view id);

// The face part a group covers: 2 "jaw, chin and inner lips", 3 "eyes", ..., "" if none.
std::string_view fdpGroupName(int group);

// The counterpart on the other side (3.7 <-> 3.12, 8.3 <-> 8.4), or the id itself for a point
// on the mid line; nullopt for an unknown id.
std::optional<std::string_view> mirroredFdp(std::string_view id);

// Every left/right twin as (left, right), the table's own left first: 3.7 / 3.12 (outer eye
// corners), 3.11 / 3.8 (inner), 8.10 / 8.9 (the Cupid's-bow peaks), ...
std::span<const std::pair<std::string_view, std::string_view>> fdpMirrorPairs();

}  // namespace lacrima::inline common
