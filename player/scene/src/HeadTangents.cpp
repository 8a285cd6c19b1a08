#include <lacrima/scene/HeadTangents.h>

#include <Eigen/Geometry>

#include <cmath>

namespace lacrima::scene {

std::vector<Eigen::Vector4f> headTangents(const HeadMesh& head) {
  const auto n = static_cast<std::size_t>(head.vertexCount());
  const bool hasNormals = head.normals.cols() == head.positions.cols();
  const bool hasUvs = head.uvs.cols() == head.positions.cols();
  std::vector<Eigen::Vector3f> alongU(n, Eigen::Vector3f::Zero()), alongV = alongU;
  if (hasUvs)
    for (const HeadSubmesh& sub : head.submeshes)
      for (const Eigen::Vector3i& t : sub.triangles) {
        const Eigen::Vector3f e1 = head.positions.col(t[1]) - head.positions.col(t[0]);
        const Eigen::Vector3f e2 = head.positions.col(t[2]) - head.positions.col(t[0]);
        const Eigen::Vector2f d1 = head.uvs.col(t[1]) - head.uvs.col(t[0]);
        const Eigen::Vector2f d2 = head.uvs.col(t[2]) - head.uvs.col(t[0]);
        const float det = d1.x() * d2.y() - d2.x() * d1.y();
        if (!(std::abs(det) > 1e-12f)) continue;
        // dp/du and dp/dv, scaled by the triangle's uv area so that larger triangles weigh more.
        const Eigen::Vector3f u = (e1 * d2.y() - e2 * d1.y()) * (det > 0 ? 1.0f : -1.0f);
        const Eigen::Vector3f v = (e2 * d1.x() - e1 * d2.x()) * (det > 0 ? 1.0f : -1.0f);
        for (int k = 0; k < 3; ++k) {
          alongU[static_cast<std::size_t>(t[k])] += u;
          alongV[static_cast<std::size_t>(t[k])] += v;
        }
      }
  std::vector<Eigen::Vector4f> tangents(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3f normal =
        hasNormals ? Eigen::Vector3f(head.normals.col(static_cast<Eigen::Index>(i)))
                   : Eigen::Vector3f::UnitZ();
    Eigen::Vector3f t = alongU[i] - normal * normal.dot(alongU[i]);
    float handedness = 1;
    if (t.norm() > 1e-12f) {
      t.normalize();
      handedness = normal.cross(t).dot(alongV[i]) < 0 ? -1.0f : 1.0f;
    } else {
      t = normal.unitOrthogonal();
    }
    tangents[i] = Eigen::Vector4f(t.x(), t.y(), t.z(), handedness);
  }
  return tangents;
}

}  // namespace lacrima::scene
