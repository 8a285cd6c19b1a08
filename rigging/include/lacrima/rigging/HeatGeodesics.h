#pragma once
// Geodesic distance by the heat method (Crane, Weischedel, Wardetzky 2013, "Geodesics in
// Heat"), factored once per mesh and solved once per set of sources.
//
// On the welded triangles of a SurfaceGraph, with per-triangle cotangents cot_i of the angle
// at corner i:
//   L   cotangent Laplacian, L_jk = 1/2 sum of cot of the angles opposite edge jk,
//       L_jj = -sum_k L_jk (negative semi-definite)
//   M   lumped mass, M_jj = 1/3 of the area of the triangles around j
//   t   = m h^2, h the mean edge length, m the time factor (1 by default)
//   1.  (M - t L) u = delta           delta = 1 at the source nodes, 0 elsewhere
//   2.  X = -grad u / |grad u|        per triangle; grad u = 1/(2A) sum_i u_i (N x e_i),
//                                     e_i the edge opposite corner i, counter-clockwise
//   3.  L phi = div X                 (div X)_i = 1/2 sum over triangles at i of
//                                     cot_k (p_j - p_i).X + cot_j (p_k - p_i).X
//   4.  d = phi - mean(phi over the component's sources), then sources exactly 0
//   5.  (straightLineBound, on by default) d = max(d, |p - nearest source of the component|):
//       a surface path is never shorter than the straight segment, so where the bound is
//       active the error can only shrink (if g >= e > d then g - e < g - d). The heat method
//       underestimates next to its sources; on the default head at rig radii (2-3 edges) a
//       neighbour can come out at half its edge length, and the bound halves the mean
//       relative error there. Off, the result is the plain heat method (for comparisons).
// Both matrices are factored with Eigen's SimplicialLDLT in the constructor; distances()
// costs two triangular solves and one pass over the triangles.
//
// Degenerate input stays finite:
//  - Cotangents share one clamped denominator per triangle, cot_i = (e_j . e_k) / max(2A,
//    1e-4 (|e_0|^2 + |e_1|^2 + |e_2|^2)), i.e. |cot| <= 5000 (angles below ~0.01 degree).
//    A common denominator keeps each triangle's stiffness a scaled Gram matrix, so L stays
//    negative semi-definite even for zero-area triangles. Such "flat" triangles get X = 0
//    (no normal, no gradient) and add nothing to the divergence.
//  - Nodes whose triangles all have zero area get a mass floor of 1e-12 x the mean mass, so
//    M - t L stays positive definite.
//  - L is singular once per connected component (constants): the first node of every
//    component is pinned to phi = 0, and a 1e-12-relative diagonal shift covers the extra
//    null directions of a component made only of zero-area triangles. Components without a
//    source have u = 0 and get +infinity.
// Heat decays like exp(-d / sqrt(t)): beyond ~700 sqrt(t) u underflows and X vanishes there,
// far more than a head ever spans in edge lengths.
#include <lacrima/rigging/SurfaceGraph.h>

#include <Eigen/Core>
#include <Eigen/SparseCholesky>

#include <vector>

namespace lacrima::rigging {

class HeatGeodesics {
 public:
  // Factors both systems. Throws std::invalid_argument for a time factor that is not
  // finite and positive, std::runtime_error if a factorisation fails.
  explicit HeatGeodesics(const SurfaceGraph& graph, double timeFactor = 1.0,
                         bool straightLineBound = true);

  HeatGeodesics(const HeatGeodesics&) = delete;
  HeatGeodesics& operator=(const HeatGeodesics&) = delete;

  // Distances per MESH vertex from the nearest of `sources` (mesh vertices in the graph; seam
  // copies share their node's value); +infinity outside the graph or in components without a
  // source. Throws std::invalid_argument for a source outside the graph or no source at all.
  Eigen::VectorXd distances(const Eigen::VectorXi& sources) const;

  double timeStep() const { return timeStep_; }

 private:
  struct Face {
    Eigen::Vector3i nodes;
    Eigen::Matrix3d gradient;  // column i: (N x e_i) / (2A), so grad u = gradient * u_corners
    Eigen::Vector3d cot;       // clamped cotangent of the angle at each corner
    bool flat = false;         // clamped: no gradient, no divergence
  };

  std::vector<Face> faces_;
  Eigen::Matrix3Xd positions_;
  std::vector<int> nodeOfVertex_;
  std::vector<int> component_;
  int componentCount_ = 0;
  std::vector<char> pinned_;  // per node: the one node of its component held at phi = 0
  bool straightLineBound_ = true;
  double timeStep_ = 0;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> heat_;     // M - t L
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> poisson_;  // -L, pinned and shifted
};

}  // namespace lacrima::rigging
