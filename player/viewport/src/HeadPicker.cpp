#include <lacrima/viewport/HeadPicker.h>

namespace lacrima::viewport {
namespace {

std::vector<Eigen::Vector3i> pickableTriangles(const HeadMesh& head,
                                               const std::vector<bool>& pickable,
                                               std::vector<int>& global, std::vector<int>& submesh,
                                               std::vector<int>& local) {
  std::vector<Eigen::Vector3i> triangles;
  int first = 0;
  for (std::size_t s = 0; s < head.submeshes.size(); ++s) {
    const auto& own = head.submeshes[s].triangles;
    if (s >= pickable.size() || pickable[s]) {
      for (std::size_t t = 0; t < own.size(); ++t) {
        triangles.push_back(own[t]);
        global.push_back(first + static_cast<int>(t));
        submesh.push_back(static_cast<int>(s));
        local.push_back(static_cast<int>(t));
      }
    }
    first += static_cast<int>(own.size());
  }
  return triangles;
}

}  // namespace

int firstTriangleOf(const HeadMesh& head, int submesh) {
  int first = 0;
  for (int s = 0; s < submesh && s < static_cast<int>(head.submeshes.size()); ++s)
    first += static_cast<int>(head.submeshes[s].triangles.size());
  return first;
}

HeadPicker::HeadPicker(const HeadMesh& head, const std::vector<bool>& pickable)
    : mesh_(head.positions, pickableTriangles(head, pickable, global_, submesh_, local_)) {}

void HeadPicker::setPositions(const Eigen::Matrix3Xf& positions) { mesh_.refit(positions); }

std::optional<SurfaceHit> HeadPicker::pick(const Ray& ray) const {
  const auto hit = mesh_.closestHit(ray);
  if (!hit) return std::nullopt;
  SurfaceHit out;
  out.triangle = global_[hit->triangle];
  out.submesh = submesh_[hit->triangle];
  out.submeshTriangle = local_[hit->triangle];
  int corner = 0;
  hit->barycentric.maxCoeff(&corner);
  out.vertex = mesh_.triangles()[hit->triangle][corner];
  out.barycentric = hit->barycentric;
  out.position = hit->point;
  out.distance = hit->distance;
  return out;
}

}  // namespace lacrima::viewport
