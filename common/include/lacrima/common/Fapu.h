#pragma once
// Facial Animation Parameter Units measured on a neutral face.
//
//   IRISD0 = mean over both eyes of (upper lid mid 3.1/3.2).y - (lower lid mid 3.3/3.4).y
//   ES0    = (left pupil 3.5).x - (right pupil 3.6).x
//   ENS0   = mean pupil y - (nose bottom 9.15).y
//   MNS0   = (9.15).y - (inner upper lip mid 2.2).y
//   MW0    = (left outer lip corner 8.3).x - (right outer lip corner 8.4).x
//   unit   = X0 / 1024 for each distance; AU = 1e-5 rad
// Positions are in the face frame (+y up, +x the face's left), so every X0 is positive on a
// correctly oriented face; anything else is reported as an error naming the points.
#include <lacrima/common/FapTable.h>

#include <Eigen/Core>

namespace lacrima::inline common {

// The feature points that define the FAPUs, in the face frame.
struct FapuReferencePoints {
  Eigen::Vector3d upperLidLeft;    // 3.1
  Eigen::Vector3d upperLidRight;   // 3.2
  Eigen::Vector3d lowerLidLeft;    // 3.3
  Eigen::Vector3d lowerLidRight;   // 3.4
  Eigen::Vector3d pupilLeft;       // 3.5
  Eigen::Vector3d pupilRight;      // 3.6
  Eigen::Vector3d noseBottom;      // 9.15
  Eigen::Vector3d innerUpperLip;   // 2.2
  Eigen::Vector3d lipCornerLeft;   // 8.3
  Eigen::Vector3d lipCornerRight;  // 8.4
};

struct FapuSet {
  // Neutral-face distances X0, in model units.
  double irisd0 = 0, es0 = 0, ens0 = 0, mns0 = 0, mw0 = 0;

  static constexpr double kDivisor = 1024.0;
  static constexpr double kAngleUnit = 1e-5;  // radians per AU

  // Size of one step of `unit`: X0/1024 for distances, 1e-5 for AU, 1 for particles,
  // 0 for None.
  double unitValue(FapUnit unit) const;
};

// Throws std::invalid_argument naming the offending points when an X0 is not positive
// (wrong orientation, swapped left/right, or points that coincide). Each eye's height enters
// IRISD0 and must be positive on its own, so one shut eye cannot hide behind the mean.
FapuSet computeFapu(const FapuReferencePoints& points);

}  // namespace lacrima::inline common
