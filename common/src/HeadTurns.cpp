#include <lacrima/common/HeadTurns.h>

#include <lacrima/common/FapTable.h>
#include <lacrima/common/Fapu.h>

#include <algorithm>
#include <cmath>

namespace lacrima::inline common {
namespace {

constexpr float kMaxValue = 16777216.0f;  // 2^24, see PoseSet.h

// A rotation channel's turn as an exact rotation. The angle is formed in double so that a
// value of 90 degrees gives cos = 0 to float precision, not to the error of value * 1e-5f.
Eigen::Quaterniond channelRotation(const FapValues& values, int fap) {
  const double angle = double(usableFapValue(values[channelIndex(fap)])) * FapuSet::kAngleUnit;
  return Eigen::Quaterniond(Eigen::AngleAxisd(angle, fapInfo(fap).positiveMotion.cast<double>()));
}

}  // namespace

float usableFapValue(float value) {
  if (!std::isfinite(value)) return 0.0f;
  return std::clamp(value, -kMaxValue, kMaxValue);
}

Eigen::Quaterniond eyeTurn(const FapValues& values, EyeSide eye) {
  // Yaw, then pitch about the yawed horizontal axis: a positive pitch looks down whatever the yaw.
  return eye == EyeSide::Left ? channelRotation(values, 23) * channelRotation(values, 25)
                              : channelRotation(values, 24) * channelRotation(values, 26);
}

Eigen::Quaterniond headTurn(const FapValues& values) {
  return channelRotation(values, 49) * channelRotation(values, 48) * channelRotation(values, 50);
}

}  // namespace lacrima::inline common
