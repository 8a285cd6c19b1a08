#include "Octree.h"

#include <algorithm>
#include <cmath>

namespace lacrima::tears {
namespace {

// Whether x lies in the box [min - h, min + edge + h]^3.
bool inGrownBox(const Eigen::Vector3d& x, const Eigen::Vector3d& min, double edge, double h) {
  for (int a = 0; a < 3; ++a)
    if (x[a] < min[a] - h || x[a] > min[a] + edge + h) return false;
  return true;
}

}  // namespace

int Octree::leafCount() const {
  return static_cast<int>(
      std::count_if(nodes_.begin(), nodes_.end(), [](const Node& n) { return n.leaf; }));
}

void Octree::find(std::span<const Eigen::Vector3d> x, double h, NeighbourList& out) {
  const std::size_t n = x.size();
  nodes_.clear();
  entries_.clear();
  out.offsets.assign(n + 1, 0);
  out.indices.clear();
  if (n == 0) return;

  Eigen::Vector3d lo = x[0], hi = x[0];
  for (const auto& p : x) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  // Root edge: node_size * 2^depth, the smallest such cube holding every particle.
  const double extent = std::max((hi - lo).maxCoeff(), 1e-12);
  double edge = std::max(nodeSize_, 1e-12);
  while (edge < extent * (1 + 1e-9) + 1e-12) edge *= 2;
  Node root;
  root.min = lo;
  root.edge = edge;
  nodes_.push_back(root);
  std::vector<int> all(n);
  for (std::size_t i = 0; i < n; ++i) all[i] = static_cast<int>(i);
  split(0, all, x, h);

  const double h2 = h * h;
  for (std::size_t i = 0; i < n; ++i) {
    const Node& leaf = nodes_[static_cast<std::size_t>(leafContaining(x[i]))];
    for (int e = leaf.firstEntry; e < leaf.firstEntry + leaf.entryCount; ++e) {
      const int j = entries_[static_cast<std::size_t>(e)];
      if (j != static_cast<int>(i) && (x[static_cast<std::size_t>(j)] - x[i]).squaredNorm() < h2)
        out.indices.push_back(j);
    }
    out.offsets[i + 1] = static_cast<int>(out.indices.size());
  }
}

// `candidates` are the particles within h of this node (its grown box).
void Octree::split(int index, std::vector<int>& candidates, std::span<const Eigen::Vector3d> x,
                   double h) {
  const Node node = nodes_[static_cast<std::size_t>(index)];
  if (node.edge <= nodeSize_ * (1 + 1e-9)) {
    Node& leaf = nodes_[static_cast<std::size_t>(index)];
    leaf.leaf = true;
    leaf.firstEntry = static_cast<std::int32_t>(entries_.size());
    leaf.entryCount = static_cast<std::int32_t>(candidates.size());
    entries_.insert(entries_.end(), candidates.begin(), candidates.end());
    return;
  }
  const double half = 0.5 * node.edge;
  for (int c = 0; c < 8; ++c) {
    const Eigen::Vector3d min =
        node.min + half * Eigen::Vector3d(c & 1, (c >> 1) & 1, (c >> 2) & 1);
    std::vector<int> inside;
    for (int p : candidates)
      if (inGrownBox(x[static_cast<std::size_t>(p)], min, half, h)) inside.push_back(p);
    if (inside.empty()) continue;  // no particle within h: the node is not created
    Node child;
    child.min = min;
    child.edge = half;
    const int childIndex = static_cast<int>(nodes_.size());
    nodes_.push_back(child);
    nodes_[static_cast<std::size_t>(index)].child[static_cast<std::size_t>(c)] = childIndex;
    split(childIndex, inside, x, h);
  }
}

int Octree::leafContaining(const Eigen::Vector3d& x) const {
  int index = 0;
  while (!nodes_[static_cast<std::size_t>(index)].leaf) {
    const Node& node = nodes_[static_cast<std::size_t>(index)];
    const double half = 0.5 * node.edge;
    int c = 0;
    for (int a = 0; a < 3; ++a)
      if (x[a] >= node.min[a] + half) c |= 1 << a;
    // Every particle lies in its own octant, which therefore exists.
    index = node.child[static_cast<std::size_t>(c)];
  }
  return index;
}

}  // namespace lacrima::tears
