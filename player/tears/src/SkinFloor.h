#pragma once
// Which free particles have left the face for good: water falling past the chin with no skin
// below it will only fall out of the simulation box, so with
// SimulationOptions::retireFallingWater it is recycled as soon as that is certain instead of
// being carried down to the box's bottom (as a fast stray that voids the pair list, and a
// closing speed that shortens the sub-step).
//
// The surface is summarised by its lowest point over each column of a horizontal grid (cells of
// edge `cell` in x and z; gravity along -y, TearSimulation::gravity()). A triangle counts in
// every column its x-z bounding box touches, with the lowest of its corners: conservative, a
// column may report skin lower than there is, never higher.
//
// A particle at x moving at v under gravity alone (nothing else acts on water in free fall
// away from the skin and other water) follows
//   y(t) = y - s t - g t^2 / 2   (s = -v_y >= 0, the downward speed),
// and reaches the box's bottom y0 at t* = (sqrt(s^2 + 2 g d) - s) / g, d = y - y0 (t* = d / s
// when g = 0). Its height never rises, and its horizontal position stays within
// R = |v_xz| t* of where it is. So if every column within R + clearance lies with its lowest
// skin point above y + clearance, the particle can never come within `clearance` of the surface
// again before it leaves the box: it is gone.
#include <Eigen/Core>
#include <Eigen/Geometry>

#include <span>
#include <vector>

namespace lacrima::tears {

class SkinFloor {
 public:
  // The lowest point of `triangles` (over `vertices`, columns of `vertices`) in each column of
  // `box` (its x-z extent; its bottom is where falling particles leave).
  void build(const Eigen::Matrix3Xd& vertices, std::span<const Eigen::Vector3i> triangles,
             const Eigen::AlignedBox3d& box, double cell);

  // Whether a particle at x with velocity v, falling under gravity g >= 0 along -y, leaves the
  // box's bottom without coming within `clearance` of the surface (see above). False for a
  // particle moving up, for one that would sweep more than kMaxColumns columns (kept, not
  // decided), and before build().
  bool fallsClear(const Eigen::Vector3d& x, const Eigen::Vector3d& v, double g,
                  double clearance) const;

  // Columns one decision may read: a particle drifting sideways so fast that its fall covers
  // more is simply kept (recycled at the box, as before).
  static constexpr int kMaxColumns = 1024;
  // Columns the floor holds at most; finer cells are widened to fit.
  static constexpr double kMaxCells = 1 << 20;

 private:
  double minX_ = 0, minZ_ = 0, bottom_ = 0, cell_ = 1;
  int columnsX_ = 0, columnsZ_ = 0;
  std::vector<double> lowest_;  // per column, row-major in z; +infinity where no surface is
};

}  // namespace lacrima::tears
