#include "SkinAttachment.h"

#include <lacrima/rigging/ClosestSurfacePoints.h>

#include <unordered_map>

namespace lacrima::rigging {

SkinAttachment attachToSkin(const HeadMesh& mesh, const std::vector<std::string>& skin,
                            const std::vector<int>& attached) {
  SkinAttachment out;
  if (attached.empty()) return out;
  std::vector<Eigen::Vector3i> triangles;
  for (const std::string& name : skin) {
    const HeadSubmesh& s = *mesh.findSubmesh(name);
    triangles.insert(triangles.end(), s.triangles.begin(), s.triangles.end());
  }
  Eigen::Matrix3Xd queries(3, static_cast<Eigen::Index>(attached.size()));
  for (std::size_t k = 0; k < attached.size(); ++k)
    queries.col(static_cast<Eigen::Index>(k)) = mesh.positions.col(attached[k]).cast<double>();
  const SurfacePoints under =
      closestSurfacePoints(mesh.positions.cast<double>(), triangles, queries);
  for (std::size_t k = 0; k < attached.size(); ++k) {
    const int t = under.triangle[static_cast<Eigen::Index>(k)];
    if (t < 0) continue;
    out.vertices.push_back(attached[k]);
    out.corners.push_back(triangles[static_cast<std::size_t>(t)]);
    out.barycentric.push_back(under.barycentric.col(static_cast<Eigen::Index>(k)));
  }
  return out;
}

std::vector<std::pair<int, float>> SkinAttachment::weights(
    const FeaturePointInfluence& skin) const {
  std::unordered_map<int, double> weightOf;
  for (std::size_t k = 0; k < skin.vertices.size(); ++k)
    weightOf[skin.vertices[k]] = skin.weights[k];
  std::vector<std::pair<int, float>> out;
  for (std::size_t k = 0; k < vertices.size(); ++k) {
    double w = 0;
    for (int c = 0; c < 3; ++c)
      if (const auto hit = weightOf.find(corners[k][c]); hit != weightOf.end())
        w += barycentric[k][c] * hit->second;
    if (w > 0) out.emplace_back(vertices[k], static_cast<float>(w));
  }
  return out;
}

}  // namespace lacrima::rigging
