#pragma once
// A starting radius for a feature point's influence, from the face's own FAPUs.
//
// Choice: r = the typical spacing between the point and its neighbours on the same facial
// contour in the MPEG-4 feature-point layout. With the falloff w(s) + w(1 - s) = 1 (see
// InfluenceFalloff.h), neighbours one radius apart then share the surface between them and
// a FAP that moves both equally moves that strip rigidly, with no dip or bulge. By FDP group:
//   2.1, 2.10 - 2.14 (jaw, chin)          MW0       the chin and jaw move as one block
//   2 other, 8 (inner and outer lips)      MW0 / 4   corner, half-way point, middle: MW0/4 apart
//   3 (eyelids, eyes)                      ES0 / 4   eye width ~ ES0/2, lid middle to corners
//   4 (eyebrows)                           ES0 / 3   inner, middle, outer over ~2/3 ES0
//   5 (cheeks)                             ES0 / 2
//   6 (tongue)                             MW0 / 4
//   9 (nose)                               ENS0 / 4  nostrils, tip and bridge
//   10 (ears)                              ES0 / 4
//   7, 11 (head, hair line)                ES0 / 2
// Surface distance keeps these radii from crossing the mouth slit or the eye opening. They are
// defaults only: the rig tunes each point.
#include <lacrima/common/Fapu.h>
#include <lacrima/rigging/DirectionalGeodesics.h>

#include <optional>
#include <string_view>

namespace lacrima::rigging {

// `featurePoint` is an FDP id "group.index", e.g. "8.3". Throws std::invalid_argument for a
// malformed id, a group outside 2-11, or a needed FAPU distance that is not positive.
double defaultInfluenceRadius(const FapuSet& fapu, std::string_view featurePoint);

// Reach along the motion, for FAPs that must not fold the skin (docs/rig.md, "Folds").
//
// A pose moves the skin by x -> x + V w(x) d, d the FAP's step (unit value times direction).
// Where w falls off along d with slope k (|dw/dl| <= k over the surface), the skin along d is
// compressed by the factor 1 - V k |d| and folds once V k |d| >= 1. The falloff's steepest
// slope is 2 / rho over a reach rho, so the pose cannot fold for |V| |d| < rho / 2: the reach
// along the motion must be at least twice the largest displacement asked of it. A round
// influence (rho = radius) gives the brows only 512 ES0 / (3 ENS0) = 214 ENS steps (10 mm on
// the default head) before they fold.
//
// The values over which a FAP is built not to fold: the brow raises 31-36 from -200 (9.6 mm
// down on the default head) to +400 (19 mm up), the squeezes 37/38 from -200 (each brow drawn
// 12 mm outward) to +100 (6 mm in: both at +176 would bring the two inner ends together, and
// there is no way to draw the skin between them further in without folding it). Other FAPs
// have none: their influence stays round.
struct FoldFreeRange {
  double min = 0;  // <= 0
  double max = 0;  // >= 0
};
std::optional<FoldFreeRange> foldFreeRange(int fap);

// Reach ahead = kReachPerDisplacement times the largest displacement ahead (range.max times
// `unitValue`), behind likewise from -range.min, neither below `radius`; across = `radius`.
// With kReachPerDisplacement = 3.5 the skin along the motion keeps at least 1 - 2 / 3.5 = 43%
// of its length for exact distances; discretisation (the fast-marching overshoot near the
// source, the piecewise-linear weights on coarse triangles) spends part of that margin.
inline constexpr double kReachPerDisplacement = 3.5;
DirectionalReach directionalReach(double radius, double unitValue, const FoldFreeRange& range);

}  // namespace lacrima::rigging
