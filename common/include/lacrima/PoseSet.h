#pragma once
// One pose per FAP, and the blending that turns FAP values into a deformed head.
//
//   p_v = R_head ( E_v ( n_v + sum_i value_i * d_{i,v} ) ) about the pivots, where
//   n_v        neutral position of vertex v,
//   d_{i,v}    pose of translational FAP i: offset of v for a value of 1 (one FAPU step),
//   E_v        the eyeball rotation (FAPs 23-26, value * 1e-5 rad about the FapTable axes,
//              yaw then pitch, about the eye's centre) for vertices of that eye, else identity,
//   R_head     the rigid head rotation (48 pitch, 49 yaw, 50 roll) about the neck pivot.
// Rotations are exact rotations, not linearised offsets, so 90-degree values stay correct.
// Normals are recomputed from the deformed triangles (shared across uv seams).
#include <lacrima/FapChannels.h>
#include <lacrima/HeadMesh.h>

#include <Eigen/Core>

#include <array>
#include <vector>

namespace lacrima {

// Sparse offsets for a FAP value of 1: vertices[k] moves by offsets.col(k) * value.
struct VertexPose {
  std::vector<int> vertices;
  Eigen::Matrix3Xf offsets;  // 3 x vertices.size()

  bool empty() const { return vertices.empty(); }
};

// Vertices that turn rigidly about a centre: an eyeball (with its cornea), or the whole head.
struct RotationGroup {
  std::vector<int> vertices;
  Eigen::Vector3f centre = Eigen::Vector3f::Zero();
};

struct PoseSet {
  int vertexCount = 0;
  std::array<VertexPose, kChannelCount> poses;  // by channelIndex(fap); empty where not translational
  RotationGroup eyeLeft, eyeRight;              // FAPs 23/25 and 24/26
  RotationGroup head;                           // FAPs 48-50; all vertices that follow the head

  // Channels with a non-empty pose or a rotation group.
  ChannelMask drivenChannels() const;
};

// Blends poses into positions and normals. Holds the topology it needs to rebuild normals,
// so per-frame work is one pass over the poses in use plus one over the triangles.
class PoseBlender {
public:
  PoseBlender(const HeadMesh& neutral, PoseSet poses);

  // Writes the deformed head for `values` (only non-zero channels cost time).
  void blend(const FapValues& values, Eigen::Matrix3Xf& positions, Eigen::Matrix3Xf& normals) const;

  const PoseSet& poses() const { return poses_; }

private:
  Eigen::Matrix3Xf neutral_;
  PoseSet poses_;
  std::vector<Eigen::Vector3i> triangles_;  // all sub-meshes
  std::vector<int> weld_;                   // vertex -> first vertex at the same position
};

}  // namespace lacrima
