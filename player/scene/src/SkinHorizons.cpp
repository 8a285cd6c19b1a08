#include <lacrima/scene/SkinHorizons.h>

#include <lacrima/scene/OverlayMasks.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <future>
#include <limits>

namespace lacrima::scene {
namespace {

// Skin points bucketed in cubes of a quarter of the reach (coarser for a tiny reach, so the grid
// stays small); a vertex looks only at the cubes that can hold a point within reach of anywhere
// in its own cube (613 of the 9 x 9 x 9 around it, a third of the volume of the 27 whole-reach
// cubes a coarser grid would hand it). Each cube keeps its points' positions side by side, which
// the inner loop reads in order.
class PointGrid {
 public:
  PointGrid(const std::vector<Eigen::Vector3f>& points, float reach) {
    low_ = Eigen::Vector3f::Constant(std::numeric_limits<float>::infinity());
    Eigen::Vector3f high = -low_;
    for (const Eigen::Vector3f& p : points) {
      low_ = low_.cwiseMin(p);
      high = high.cwiseMax(p);
    }
    if (points.empty()) low_ = high = Eigen::Vector3f::Zero();
    // At most 128 cubes along the longest side, whatever the reach.
    side_ = std::max({0.25f * reach, (high - low_).maxCoeff() / 128, 1e-6f});
    size_ = ((high - low_) / side_).array().floor().cast<int>() + 1;
    cells_.resize(static_cast<std::size_t>(size_.prod()));
    for (const Eigen::Vector3f& p : points) cells_[index(cell(p))].push_back(p);
    const int span = static_cast<int>(std::ceil(reach / side_));
    for (int z = -span; z <= span; ++z)
      for (int y = -span; y <= span; ++y)
        for (int x = -span; x <= span; ++x) {
          // Nearest two points of cubes this far apart: (|offset| - 1) sides along each axis.
          const Eigen::Vector3i gap = (Eigen::Vector3i(x, y, z).cwiseAbs().array() - 1).max(0);
          if (float(gap.squaredNorm()) * side_ * side_ <= reach * reach)
            offsets_.emplace_back(x, y, z);
        }
  }
  template <typename Visit>
  void near(const Eigen::Vector3f& p, Visit visit) const {
    const Eigen::Vector3i c = cell(p);
    for (const Eigen::Vector3i& offset : offsets_) {
      const Eigen::Vector3i at = c + offset;
      if ((at.array() < 0).any() || (at.array() >= size_.array()).any()) continue;
      for (const Eigen::Vector3f& q : cells_[index(at)]) visit(q);
    }
  }

 private:
  Eigen::Vector3i cell(const Eigen::Vector3f& p) const {
    return ((p - low_) / side_).array().floor().cast<int>().max(0).min(size_.array() - 1);
  }
  std::size_t index(const Eigen::Vector3i& c) const {
    return static_cast<std::size_t>((c.z() * size_.y() + c.y()) * size_.x() + c.x());
  }
  float side_;
  Eigen::Vector3f low_;
  Eigen::Vector3i size_;
  std::vector<std::vector<Eigen::Vector3f>> cells_;
  std::vector<Eigen::Vector3i> offsets_;
};

// The 45-degree sector (0 to 7, counter-clockwise from +x) of direction (x, y), by comparisons
// against tan(22.5 degrees) instead of an atan2 per point.
int sectorOf(float x, float y) {
  constexpr float kTan = 0.41421356f;
  if (std::abs(y) <= kTan * std::abs(x)) return x >= 0 ? 0 : 4;
  if (std::abs(x) <= kTan * std::abs(y)) return y >= 0 ? 2 : 6;
  if (y >= 0) return x >= 0 ? 1 : 3;
  return x >= 0 ? 7 : 5;
}

}  // namespace

std::vector<Horizons> skinHorizons(const HeadMesh& head,
                                   const std::vector<Eigen::Vector4f>& tangents, float reach) {
  std::vector<Horizons> horizons(static_cast<std::size_t>(head.vertexCount()), Horizons{});
  const HeadSubmesh* skin = head.findSubmesh("skin");
  if (!skin || tangents.size() != horizons.size() || head.normals.cols() != head.positions.cols())
    return horizons;
  if (!(reach > 0)) {
    const auto eye = eyeSphere(head, "eye_l");
    reach = eye ? 4 * eye->radius : (head.boundsMax().y() - head.boundsMin().y()) / 5;
  }
  // Occluders: one copy of each skin point (uv seams duplicate positions).
  const std::vector<int> weld = weldCoincidentVertices(head.positions);
  std::vector<Eigen::Vector3f> points;
  for (int v = skin->firstVertex; v < skin->firstVertex + skin->vertexCount; ++v)
    if (weld[static_cast<std::size_t>(v)] == v) points.emplace_back(head.positions.col(v));
  const PointGrid grid(points, reach);
  // Skin nearer than this is the vertex's own fold (the occlusion darkens creases already);
  // per-vertex shadows from it came out as wedges along the folds, the triangles being big.
  const float nearest = 0.25f * reach;
  auto horizonsOf = [&](int first, int end) {
    for (int v = first; v < end; ++v) {
      const Eigen::Vector3f p = head.positions.col(v), n = head.normals.col(v);
      const Eigen::Vector4f& frame = tangents[static_cast<std::size_t>(v)];
      const Eigen::Vector3f t = frame.head<3>(), b = frame.w() * n.cross(t);
      Horizons& h = horizons[static_cast<std::size_t>(v)];
      grid.near(p, [&](const Eigen::Vector3f& q) {
        const Eigen::Vector3f d = q - p;
        const float height = d.dot(n);
        if (height <= 0) return;  // below the tangent plane: most points of a convex patch
        const float squared = d.squaredNorm();
        if (squared > reach * reach || squared < nearest * nearest) return;
        float& horizon = h[static_cast<std::size_t>(sectorOf(d.dot(t), d.dot(b)))];
        horizon = std::max(horizon, height / std::sqrt(squared));
      });
    }
  };
  // Two halves at once (about 35 ms for the default head on one core): each vertex writes only
  // its own horizons.
  const int middle = skin->firstVertex + skin->vertexCount / 2;
  auto firstHalf = std::async(std::launch::async, horizonsOf, skin->firstVertex, middle);
  horizonsOf(middle, skin->firstVertex + skin->vertexCount);
  firstHalf.get();
  return horizons;
}

}  // namespace lacrima::scene
