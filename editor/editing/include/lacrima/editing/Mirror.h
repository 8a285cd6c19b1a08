#pragma once
// Left/right mirroring of poses and the symmetric-edit partner of a channel.
//
// Mirroring is the reflection x -> -x of the face frame. Each channel c maps to
// m(c) = mirroredFap(c) (6 stretch_l_cornerlip <-> 7 stretch_r_cornerlip, 69 <-> 70, centre
// FAPs to themselves) and its value v becomes s(c) v with s(c) = -1 when mirrorNegates(c)
// (sideways centre motions and yaw/roll rotations, see FapTable.h), else +1. m is an
// involution and s(m(c)) = s(c), so mirroring twice gives the pose back exactly.
#include <lacrima/common/Keyframes.h>

#include <optional>
#include <utility>

namespace lacrima::editing {

// The key with every set channel moved to its mirror channel (time and mode unchanged).
Keyframe mirrored(const Keyframe& key);

// Symmetric editing: setting `fap` to `value` also sets the returned channel and value, or
// nothing for centre channels (a centre channel is its own mirror).
std::optional<std::pair<int, float>> symmetricPartner(int fap, float value);

}  // namespace lacrima::editing
