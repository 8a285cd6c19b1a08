#pragma once
// Influence weights of feature points: the falloff of SURFACE distance from the point.
//
//   w(v) = influenceFalloff(d(v) / r),   d = geodesic distance from the point's sources
// A feature point on a vertex has that vertex as its source; one inside a triangle has the
// triangle's three corners, each at distance 0, so all three get weight 1 and the point
// itself (any barycentric mix of them) moves exactly like them. Because d is measured over
// the surface, the upper and lower lip (or eyelid), which touch in space, are far apart
// whenever the way round the mouth corner (or eye corner) is longer than r.
//
// Build one InfluenceWeights per surface (e.g. the skin's SurfaceGraph) and query it per
// feature point. With GeodesicMethod::Dijkstra each query searches only the disc of radius r
// (cut-off), so cost follows the disc's size; with GeodesicMethod::Heat both systems are
// factored once here and each query costs two solves over the whole surface, for distances
// that converge under refinement, with the straight-line bound on (see DijkstraGeodesics.h,
// HeatGeodesics.h; `lacrima-bench geodesics` prints what each costs and gets wrong).
#include <lacrima/common/PoseBaking.h>
#include <lacrima/rigging/DirectionalGeodesics.h>
#include <lacrima/rigging/HeatGeodesics.h>
#include <lacrima/rigging/SurfaceGraph.h>

#include <Eigen/Core>

#include <memory>

namespace lacrima::rigging {

enum class GeodesicMethod { Dijkstra, Heat };

class InfluenceWeights {
 public:
  // Keeps its own copy of the graph. `heatTimeFactor` is m in t = m h^2 (Heat only).
  InfluenceWeights(const SurfaceGraph& graph, GeodesicMethod method, double heatTimeFactor = 1.0);

  // Weights of the mesh vertices within surface distance `radius` of the nearest source
  // (mesh vertices in the graph; seam copies included): listed in increasing vertex order,
  // each in (0, 1], exactly 1 at the sources and their copies; vertices at d >= radius are not
  // listed. Throws std::invalid_argument for a radius that is not finite and positive, or a
  // source outside the graph.
  FeaturePointInfluence compute(const Eigen::VectorXi& sources, double radius) const;
  FeaturePointInfluence atVertex(int vertex, double radius) const;
  FeaturePointInfluence atTriangle(const Eigen::Vector3i& corners, double radius) const;

  // The same listing from precomputed per-vertex distances (+infinity for unreachable).
  static FeaturePointInfluence fromDistances(const Eigen::VectorXd& distances, double radius);

  // Weights influenceFalloff(s) of the normalised distance s in the metric stretched along
  // `direction` (DirectionalGeodesics.h), whatever this object's method: the heat method here
  // is round. The same listing as compute(), for a FAP whose motion must not fold the skin
  // (docs/rig.md, "Folds"). Throws as directionalDistances does.
  FeaturePointInfluence directional(const Eigen::VectorXi& sources, const Eigen::Vector3d& origin,
                                    const Eigen::Vector3d& direction,
                                    const DirectionalReach& reach) const;

  GeodesicMethod method() const { return method_; }
  const SurfaceGraph& graph() const { return graph_; }

 private:
  SurfaceGraph graph_;
  GeodesicMethod method_;
  std::unique_ptr<HeatGeodesics> heat_;  // factored systems, Heat only
};

}  // namespace lacrima::rigging
