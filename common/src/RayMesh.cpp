#include <lacrima/common/RayMesh.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace lacrima::inline common {
namespace {

constexpr int kLeafSize = 4;
// Relative size of det below which the ray counts as parallel to the face (or the face as
// degenerate): det = d . (e1 x e2) against |e1| |e2| with |d| = 1, i.e. the sine of the angle
// between ray and plane times the sine of the triangle's smallest-corner-spanning angle.
constexpr double kParallel = 1e-12;
constexpr double kEdgeSlack = 1e-9;

// Where the ray enters and leaves `box`, clipped to [0, limit]: the slab method, one interval
// per axis, t = (plane - o) / d. An axis the ray runs parallel to (d = 0) keeps every t when
// the origin is between its planes and none otherwise; that case is tested explicitly because
// (plane - o) * inf is NaN when o lies on the plane.
bool entersBox(const Eigen::AlignedBox3f& box, const Eigen::Vector3d& origin,
               const Eigen::Vector3d& inverse, double limit, double& entry) {
  double near = 0, far = limit;
  for (int k = 0; k < 3; ++k) {
    const double lo = box.min()[k], hi = box.max()[k];
    if (std::isinf(inverse[k])) {
      if (origin[k] < lo || origin[k] > hi) return false;
      continue;
    }
    double t0 = (lo - origin[k]) * inverse[k], t1 = (hi - origin[k]) * inverse[k];
    if (t0 > t1) std::swap(t0, t1);
    near = std::max(near, t0);
    far = std::min(far, t1);
    if (!(near <= far)) return false;  // also false for NaN boxes (non-finite vertices)
  }
  entry = near;
  return true;
}

}  // namespace

std::optional<RayHit> intersectRayTriangle(const Ray& ray, const Eigen::Vector3d& a,
                                           const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d e1 = b - a, e2 = c - a;
  const Eigen::Vector3d p = ray.direction.cross(e2);
  const double det = e1.dot(p);
  const double scale = e1.norm() * e2.norm() * ray.direction.norm();
  if (!(std::abs(det) > kParallel * scale)) return std::nullopt;  // parallel, degenerate or NaN
  const double inverse = 1.0 / det;
  const Eigen::Vector3d s = ray.origin - a;
  const double u = s.dot(p) * inverse;
  if (u < -kEdgeSlack || u > 1 + kEdgeSlack) return std::nullopt;
  const Eigen::Vector3d q = s.cross(e1);
  const double v = ray.direction.dot(q) * inverse;
  if (v < -kEdgeSlack || u + v > 1 + kEdgeSlack) return std::nullopt;
  const double t = e2.dot(q) * inverse;
  if (!(t > 0) || !std::isfinite(t)) return std::nullopt;
  RayHit hit;
  hit.barycentric = Eigen::Vector3d(1 - u - v, u, v);
  hit.distance = t;
  hit.point = ray.origin + t * ray.direction;
  return hit;
}

RayMesh::RayMesh(const Eigen::Matrix3Xf& vertices, std::vector<Eigen::Vector3i> triangles)
    : vertices_(vertices), triangles_(std::move(triangles)) {
  const Eigen::Index n = vertices_.cols();
  std::vector<Eigen::Vector3f> centroids(triangles_.size());
  for (std::size_t t = 0; t < triangles_.size(); ++t) {
    const Eigen::Vector3i& tri = triangles_[t];
    for (int k = 0; k < 3; ++k)
      if (tri[k] < 0 || tri[k] >= n)
        throw std::invalid_argument("RayMesh: triangle " + std::to_string(t) + " has vertex " +
                                    std::to_string(tri[k]) + ", expected 0 to " +
                                    std::to_string(n - 1));
    centroids[t] = (vertices_.col(tri[0]) + vertices_.col(tri[1]) + vertices_.col(tri[2])) / 3;
  }
  order_.resize(triangles_.size());
  for (std::size_t t = 0; t < order_.size(); ++t) order_[t] = static_cast<int>(t);
  if (order_.empty()) return;
  nodes_.reserve(2 * order_.size() / kLeafSize + 2);
  build(0, static_cast<int>(order_.size()), centroids);
}

int RayMesh::build(int first, int count, const std::vector<Eigen::Vector3f>& centroids) {
  const int index = static_cast<int>(nodes_.size());
  nodes_.emplace_back();
  Eigen::AlignedBox3f bounds, centres;
  for (int i = first; i < first + count; ++i) {
    const Eigen::Vector3i& tri = triangles_[order_[i]];
    for (int k = 0; k < 3; ++k) bounds.extend(vertices_.col(tri[k]));
    centres.extend(centroids[order_[i]]);
  }
  nodes_[index].box = bounds;
  if (count <= kLeafSize) {
    nodes_[index].first = first;
    nodes_[index].count = count;
    return index;
  }
  // Median of the centroids along the widest axis of their box: balanced, so the depth stays
  // log2(n / 4) whatever the triangles' sizes (NaN centroids just land on one side).
  int axis = 0;
  centres.sizes().maxCoeff(&axis);
  const int half = count / 2;
  std::nth_element(order_.begin() + first, order_.begin() + first + half,
                   order_.begin() + first + count,
                   [&](int x, int y) { return centroids[x][axis] < centroids[y][axis]; });
  const int left = build(first, half, centroids);
  const int right = build(first + half, count - half, centroids);
  nodes_[index].left = left;
  nodes_[index].right = right;
  return index;
}

void RayMesh::refit(const Eigen::Matrix3Xf& vertices) {
  if (vertices.cols() != vertices_.cols())
    throw std::invalid_argument("RayMesh::refit: " + std::to_string(vertices.cols()) +
                                " vertices, the mesh has " + std::to_string(vertices_.cols()));
  vertices_ = vertices;
  if (!nodes_.empty()) refitNode(0);
}

Eigen::AlignedBox3f RayMesh::refitNode(int index) {
  const Node& node = nodes_[index];  // the vector does not grow here: the reference holds
  Eigen::AlignedBox3f box;
  if (node.count > 0) {
    for (int i = node.first; i < node.first + node.count; ++i)
      for (int k = 0; k < 3; ++k) box.extend(vertices_.col(triangles_[order_[i]][k]));
  } else {
    box = refitNode(node.left);
    box.extend(refitNode(node.right));
  }
  nodes_[index].box = box;
  return box;
}

std::optional<RayHit> RayMesh::closestHit(const Ray& input) const {
  const double length = input.direction.norm();
  if (nodes_.empty() || !(length > 0) || !std::isfinite(length) || !input.origin.allFinite())
    return std::nullopt;
  const Ray ray{input.origin, input.direction / length};
  const Eigen::Vector3d inverse = ray.direction.cwiseInverse();  // +-inf on axis-parallel rays

  std::optional<RayHit> best;
  double limit = std::numeric_limits<double>::infinity();
  double entry = 0;
  if (!entersBox(nodes_[0].box, ray.origin, inverse, limit, entry)) return std::nullopt;
  // Depth-first, nearer child first; a box entered beyond the best hit so far is skipped. The
  // stack holds (node, entry) pairs; depth is about log2(n / 4), 64 is ample for any mesh.
  struct Pending {
    int node;
    double entry;
  };
  std::vector<Pending> stack;
  stack.reserve(64);
  stack.push_back({0, entry});
  while (!stack.empty()) {
    const Pending pending = stack.back();
    stack.pop_back();
    if (pending.entry >= limit) continue;
    const Node& node = nodes_[pending.node];
    if (node.count > 0) {
      for (int i = node.first; i < node.first + node.count; ++i) {
        const Eigen::Vector3i& tri = triangles_[order_[i]];
        auto hit = intersectRayTriangle(ray, vertices_.col(tri[0]).cast<double>(),
                                        vertices_.col(tri[1]).cast<double>(),
                                        vertices_.col(tri[2]).cast<double>());
        if (hit && hit->distance < limit) {
          limit = hit->distance;
          hit->triangle = order_[i];
          best = hit;
        }
      }
      continue;
    }
    double nearEntry = 0, farEntry = 0;
    int nearChild = node.left, farChild = node.right;
    bool nearHit = entersBox(nodes_[nearChild].box, ray.origin, inverse, limit, nearEntry);
    bool farHit = entersBox(nodes_[farChild].box, ray.origin, inverse, limit, farEntry);
    if (nearHit && farHit && farEntry < nearEntry) {
      std::swap(nearChild, farChild);
      std::swap(nearEntry, farEntry);
    } else if (!nearHit && farHit) {
      std::swap(nearChild, farChild);
      std::swap(nearEntry, farEntry);
      std::swap(nearHit, farHit);
    }
    // Pushed far first so the near one is popped next.
    if (farHit) stack.push_back({farChild, farEntry});
    if (nearHit) stack.push_back({nearChild, nearEntry});
  }
  return best;
}

}  // namespace lacrima::inline common
