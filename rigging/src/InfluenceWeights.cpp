#include <lacrima/rigging/InfluenceWeights.h>

#include <lacrima/rigging/DijkstraGeodesics.h>
#include <lacrima/rigging/InfluenceFalloff.h>

#include <cmath>
#include <stdexcept>

namespace lacrima::rigging {

namespace {

void checkRadius(double radius) {
  if (!std::isfinite(radius) || radius <= 0)
    throw std::invalid_argument("InfluenceWeights: the radius must be finite and > 0");
}

}  // namespace

InfluenceWeights::InfluenceWeights(const SurfaceGraph& graph, GeodesicMethod method,
                                   double heatTimeFactor)
    : graph_(graph), method_(method) {
  if (method_ == GeodesicMethod::Heat)
    heat_ = std::make_unique<HeatGeodesics>(graph_, heatTimeFactor);
}

FeaturePointInfluence InfluenceWeights::compute(const Eigen::VectorXi& sources,
                                                double radius) const {
  checkRadius(radius);
  const Eigen::VectorXd d = method_ == GeodesicMethod::Heat
                                ? heat_->distances(sources)
                                : dijkstraDistances(graph_, sources, Eigen::VectorXd(), radius);
  return fromDistances(d, radius);
}

FeaturePointInfluence InfluenceWeights::atVertex(int vertex, double radius) const {
  return compute(Eigen::VectorXi::Constant(1, vertex), radius);
}

FeaturePointInfluence InfluenceWeights::atTriangle(const Eigen::Vector3i& corners,
                                                   double radius) const {
  return compute(Eigen::VectorXi(corners), radius);
}

FeaturePointInfluence InfluenceWeights::directional(const Eigen::VectorXi& sources,
                                                    const Eigen::Vector3d& origin,
                                                    const Eigen::Vector3d& direction,
                                                    const DirectionalReach& reach) const {
  // Normalised already: a radius of 1.
  return fromDistances(directionalDistances(graph_, sources, origin, direction, reach), 1.0);
}

FeaturePointInfluence InfluenceWeights::fromDistances(const Eigen::VectorXd& distances,
                                                      double radius) {
  checkRadius(radius);
  FeaturePointInfluence out;
  for (Eigen::Index v = 0; v < distances.size(); ++v) {
    // Inside the rim s <= 1 - 2^-53, so w >= 2^-105: still a positive float. Only d >= r,
    // +infinity and NaN give 0, and those vertices are left out.
    const auto w = static_cast<float>(influenceFalloff(distances[v] / radius));
    if (w > 0.0f) {
      out.vertices.push_back(static_cast<int>(v));
      out.weights.push_back(w);
    }
  }
  return out;
}

}  // namespace lacrima::rigging
