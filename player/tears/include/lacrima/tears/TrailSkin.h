#pragma once
// Points stored on the skin so they follow it: a triangle, barycentric weights and a height
// along the triangle's normal,
//   x = w0 v0 + w1 v1 + w2 v2 + height n,   n = (v1 - v0) x (v2 - v0) / |...|,
// re-evaluated from the current vertex positions every frame (the trail rides on the face as it
// deforms). Closest-point queries walk the skin from seed triangles (those the drop's particles
// touch) to vertex-sharing neighbours while the distance falls, so a query costs a few dozen
// triangles however large the head is.
#include <lacrima/tears/ParticleSet.h>

#include <Eigen/Core>

#include <memory>
#include <span>
#include <vector>

namespace lacrima::tears {

struct SkinAnchor {
  int triangle = -1;
  Eigen::Vector3d barycentric{1, 0, 0};
  double height = 0;
};

class TrailSkin {
 public:
  // Triangles by head vertex index, counter-clockwise outside (the simulation's skin order, so
  // a particle's contact triangle is an index into them).
  explicit TrailSkin(std::vector<Eigen::Vector3i> triangles);

  // The head positions of this frame; must stay alive while the skin is queried.
  void bind(const Eigen::Matrix3Xf& positions) { positions_ = &positions; }
  void unbind() { positions_ = nullptr; }
  bool bound() const { return positions_ != nullptr; }
  int triangleCount() const { return static_cast<int>(tables_->triangles.size()); }
  // The largest vertex index the triangles use (positions must have more columns).
  int maxVertex() const { return tables_->maxVertex; }

  Eigen::Vector3d vertex(int v) const { return positions_->col(v).cast<double>(); }
  // Unit outward normal, or zero for a degenerate triangle.
  Eigen::Vector3d normal(int triangle) const;
  Eigen::Vector3d point(const SkinAnchor& anchor) const;

  // The closest skin point to x found from the seeds (height 0); triangle -1 if no seed is valid.
  SkinAnchor closest(const Eigen::Vector3d& x, std::span<const int> seeds) const;
  // Seeds for closest(): the distinct skin triangles that `members` (particle indices) touch, in
  // particle order, at most kMaxSeeds. Contacts on other collision surfaces (the eyes, numbered
  // past the skin's triangles) are not skin.
  static constexpr std::size_t kMaxSeeds = 32;
  void contactSeeds(std::span<const SkinContact> contacts, std::span<const int> members,
                    std::vector<int>& seeds) const;

 private:
  // Never change after construction, so copies (a trail builder kept with every player
  // checkpoint) share them: half a megabyte on the default head.
  struct Tables {
    std::vector<Eigen::Vector3i> triangles;
    std::vector<int> vertexStart, vertexTriangles;  // CSR: triangles around each vertex
    int maxVertex = -1;
  };
  std::shared_ptr<const Tables> tables_;
  const Eigen::Matrix3Xf* positions_ = nullptr;
};

}  // namespace lacrima::tears
