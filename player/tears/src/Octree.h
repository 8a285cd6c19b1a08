#pragma once
// The 2009 thesis's modified octree, kept for comparison with the grid. The root cube covers all
// particles; a node is split while its edge exceeds node_size and some particle lies within h
// of it ("CreateNodes Modified"). A leaf lists every particle inside its box grown by h, so the
// neighbours of a particle are all found in the one leaf that contains it.
#include <lacrima/tears/NeighbourSearch.h>

#include <array>
#include <cstdint>

namespace lacrima::tears {

class Octree final : public NeighbourSearch {
 public:
  explicit Octree(double nodeSize) : nodeSize_(nodeSize) {}
  void find(std::span<const Eigen::Vector3d> positions, double h, NeighbourList& out) override;

  int nodeCount() const { return static_cast<int>(nodes_.size()); }
  int leafCount() const;

 private:
  struct Node {
    Eigen::Vector3d min;
    double edge = 0;
    std::array<std::int32_t, 8> child{-1, -1, -1, -1, -1, -1, -1, -1};
    std::int32_t firstEntry = 0, entryCount = 0;  // leaves: range in entries_
    bool leaf = false;
  };
  void split(int node, std::vector<int>& candidates, std::span<const Eigen::Vector3d> x, double h);
  int leafContaining(const Eigen::Vector3d& x) const;

  double nodeSize_;
  std::vector<Node> nodes_;
  std::vector<int> entries_;  // particle indices listed per leaf
};

}  // namespace lacrima::tears
