#pragma once
// The rigid turns of the rotational FAPs, as PoseBlender applies them (PoseSet.h): each eyeball
// E = R_yaw * R_pitch (left 23 / 25, right 24 / 26), the head R_head = R_yaw(49) * R_pitch(48) *
// R_roll(50), angles value * 1e-5 rad about the FapTable axes. Shared by the blender and the
// exporters that carry the turns as joint rotations, so both turn the same way.
#include <lacrima/common/FapChannels.h>

#include <Eigen/Geometry>

namespace lacrima::inline common {

// A channel value as the blender uses it: not finite counts as 0 (one corrupt channel must not
// blank the face), magnitudes beyond 2^24 (the integers float holds exactly) are clamped.
float usableFapValue(float value);

enum class EyeSide { Left, Right };

Eigen::Quaterniond eyeTurn(const FapValues& values, EyeSide eye);
Eigen::Quaterniond headTurn(const FapValues& values);

}  // namespace lacrima::inline common
