#pragma once
// Distance over a surface in a metric stretched along one direction: how far the influence of
// a FAP that moves its feature point p along the unit vector u reaches ahead of the motion,
// behind it and across it (docs/rig.md, "Folds").
//
// A step e inside triangle T (normal n_T) costs
//   |e|_T = sqrt( (e . a_T / rho_T)^2 + (e . c_T / across)^2 )
//   a_T   = u projected onto T's plane and normalised, c_T = n_T x a_T (across the motion)
//   rho_T = ahead when T's centroid lies ahead of p ((centroid - p) . u > 0), else behind
// so a length `ahead` of surface straight ahead of p, `behind` straight behind it or `across`
// to the side costs 1. Where u is normal to T (its projection shorter than 1e-6) the motion has
// no part along T and T is round with radius `across`. The metric is Riemannian per triangle,
// measured in T's plane, so a slope the motion climbs is stretched along the slope, not along
// u's own axis.
//
// Solver: fast marching with the semi-Lagrangian triangle update (Tsitsiklis 1995, "Efficient
// algorithms for globally optimal trajectories"; Bornemann & Rasch 2006, "Finite-element
// discretization of static Hamilton-Jacobi equations based on a local variational
// principle"): with corners A, B known, C gets
//   min over lambda in [0, 1] of (1 - lambda) s_A + lambda s_B + |C - (A + lambda (B - A))|_T
// in closed form in T's metric plane, besides the edge updates s_A + |C - A|_T. Nodes are
// settled in increasing order with a heap and reopened when a later update lowers them (label
// correcting), so the result is the scheme's fixed point for any triangle shape: obtuse
// triangles, which the stretch makes of most, included. The scheme is first order; next to a
// point source it overshoots where the stretch is strong. On a lattice of 64 columns tilted
// 45 degrees, stretched 3:1 (across 0.25, ahead 0.75, behind 0.5 of a width of 2), distances
// from 0.3 to 0.9 come out 5.8% long on average, 22% at worst (a strip straight ahead of the
// source), and the weights' steepest slope along the motion is 1.13 times the exact 2 / ahead
// (1.08 with 128 columns); edge paths alone (Dijkstra in the same metric) give 1.87 times
// (tests/rigging/GeodesicsTest.cpp). Round (equal reaches) it is within 5% of the plane's
// Euclidean distance and never above Dijkstra's.
#include <lacrima/rigging/SurfaceGraph.h>

#include <Eigen/Core>

namespace lacrima::rigging {

// Lengths of surface, in model units, that cost a distance of 1 in each direction.
struct DirectionalReach {
  double across = 0;  // to either side of the motion
  double ahead = 0;   // along the motion (a positive FAP value moves the point this way)
  double behind = 0;  // against it
};

// Normalised distance per MESH vertex (size graph.meshVertexCount; seam copies share their
// node's value) from the nearest of `sources` (mesh vertices in the graph, at 0), in the metric
// above; `origin` is p, `direction` u (normalised here). Only values below 1 are computed: the
// rest, unreachable vertices and vertices outside the graph get +infinity. Throws
// std::invalid_argument for a source outside the graph, a reach that is not finite and
// positive, a zero or non-finite direction or a non-finite origin.
Eigen::VectorXd directionalDistances(const SurfaceGraph& graph, const Eigen::VectorXi& sources,
                                     const Eigen::Vector3d& origin,
                                     const Eigen::Vector3d& direction,
                                     const DirectionalReach& reach);

}  // namespace lacrima::rigging
