#pragma once
// A generated stand-in for the skin until the rigged head is available, and a fixed scene for
// tests and benchmarks: a face-sized patch of a vertical cylinder (the face wraps around the
// vertical axis), facing +z, tilted about the x axis like a cheek, in decimetres like the
// default head. Two tear sources sit near its top, 0.6 dm apart like eyes.
#include <Eigen/Core>
#include <Eigen/Geometry>

#include <vector>

namespace lacrima::tears {

struct CheekSheetOptions {
  double width = 1.6, height = 2.4;  // dm
  double cylinderRadius = 1.0;       // horizontal curvature of the face
  double tiltDegrees = 20;           // top leans back by this (normal points forward and up)
  double edge = 0.05;                // target triangle edge length
  // Stress geometry: collapse one row of vertices onto the row above (a strip of zero-area
  // triangles across the middle) and add this many extra zero-area triangles (repeated and
  // collinear vertices) scattered over the sheet.
  bool collapsedRow = false;
  int extraDegenerateTriangles = 0;
};

struct SyntheticSkin {
  Eigen::Matrix3Xf positions;
  std::vector<Eigen::Vector3i> triangles;   // counter-clockwise seen from the front (+z side)
  Eigen::Vector3d leftSource, rightSource;  // just in front of the sheet near its top
  Eigen::Vector3d centre;                   // of the sheet's bounding box
  double radius = 0;                        // half the sheet's height ("head radius" stand-in)
};

SyntheticSkin makeCheekSheet(const CheekSheetOptions& options = {});

// A chin, or a nose tip: a sphere, outside facing out, whose lower half is an overhang that
// water reaches by running down its front. Latitude-longitude rings about the x axis, so the
// poles lie to the sides and the lowest point (where drops gather) is a regular patch of
// mesh. Both sources sit on the front, `sourceDegrees` above the equator, 0.1 radii apart.
struct ChinSphereOptions {
  double radius = 0.3;        // dm: a chin's curvature
  double edge = 0.03;         // target triangle edge length
  double sourceDegrees = 45;  // latitude of the sources on the front (+z)
};

SyntheticSkin makeChinSphere(const ChinSphereOptions& options = {});

// The sheet moved rigidly: x' = R x + t about the sheet's centre.
Eigen::Matrix3Xf movedSheet(
    const SyntheticSkin& sheet, const Eigen::Vector3d& translation,
    const Eigen::AngleAxisd& rotation = Eigen::AngleAxisd(0, Eigen::Vector3d::UnitX()));

}  // namespace lacrima::tears
