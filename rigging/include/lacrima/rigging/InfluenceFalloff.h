#pragma once
// The falloff of a feature point's influence with surface distance: the C1 quadratic
// B-spline shape, with s = d / r,
//   w(s) = 1 - 2 s^2        0   <= s <= 1/2
//   w(s) = 2 (1 - s)^2      1/2 <  s <  1
//   w(s) = 0                s >= 1
// w(0) = 1 with w'(0) = 0 (no cone at the feature point), w(1/2) = 1/2 with w' = -2 from both
// sides (no crease), w(1) = 0 with w'(1) = 0 (no step at the rim). Also w(s) + w(1 - s) = 1:
// two feature points one radius apart share the surface between them like a partition of
// unity, which InfluenceRadius.h uses to pick default radii.
namespace lacrima::rigging {

// w(s) as above; s <= 0 gives 1 and s >= 1 or NaN gives 0, so the value is always in [0, 1].
inline double influenceFalloff(double s) {
  if (!(s < 1.0)) return 0.0;
  if (s <= 0.0) return 1.0;
  if (s <= 0.5) return 1.0 - 2.0 * s * s;
  const double r = 1.0 - s;
  return 2.0 * r * r;
}

}  // namespace lacrima::rigging
