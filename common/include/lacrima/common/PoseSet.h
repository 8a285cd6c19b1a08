#pragma once
// One pose per FAP, and the blending that turns FAP values into a deformed head.
//
//   p_v = R_head ( E_v ( n_v + sum_i value_i * d_{i,v} ) ) about the pivots, where
//   n_v        neutral position of vertex v,
//   d_{i,v}    pose of linear FAP i: offset of v for a value of 1 (one FAPU step); the
//              translations, thrust 27/28, pupil dilation 29/30 and tongue roll 47,
//   E_v        the eyeball rotation for vertices of that eye, else identity:
//                E = R_yaw(a23) * R_pitch(a25) (left; 24 and 26 for the right eye),
//              a = value * 1e-5 rad about the FapTable axes. This is yaw then pitch about the
//              turned horizontal axis (a Fick gimbal), so a positive pitch looks down whatever
//              the yaw. The centre is the eye's neutral centre carried by the eyeball's mean
//              translation, c' = c + sum_i value_i * mean_{v in eye} d_{i,v}, so a thrust
//              eyeball still turns in place.
//   R_head     the rigid head rotation about the neck pivot,
//                R_head = R_yaw(a49) * R_pitch(a48) * R_roll(a50):
//              yaw about the neck's vertical, then nod about the turned ear-to-ear axis, then
//              roll about the face's own forward axis (the usual neck gimbal).
// Rotations are exact rotations, not linearised offsets, so 90-degree values stay correct.
// Normals are recomputed from the deformed triangles (shared across uv seams).
//
// Values that are not finite count as 0 (one corrupt channel must not blank the face), and
// magnitudes beyond 2^24 (the integers float holds exactly; 16k FAPU distances) are clamped,
// so absurd input gives an absurd but finite head.
#include <lacrima/common/FapChannels.h>
#include <lacrima/common/HeadMesh.h>

#include <Eigen/Core>

#include <array>
#include <vector>

namespace lacrima::inline common {

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
  // By channelIndex(fap). Empty for channels with no linear pose: high-level FAPs 1-2, the
  // rotations 23-26 and 48-50 (see the groups below) and the tear channels.
  std::array<VertexPose, kChannelCount> poses;
  RotationGroup eyeLeft, eyeRight;  // FAPs 23/25 and 24/26
  RotationGroup head;               // FAPs 48-50; all vertices that follow the head

  // Channels with a non-empty pose or a rotation group.
  ChannelMask drivenChannels() const;
};

// Blends poses into positions and normals. Holds the topology it needs to rebuild normals,
// so per-frame work is one pass over the poses in use plus one over the triangles.
class PoseBlender {
 public:
  // Throws std::invalid_argument when `poses` does not fit `neutral` (vertex count, an index
  // out of range, offsets of the wrong size, a non-finite centre) or a triangle of `neutral`
  // names a missing vertex. An entirely empty PoseSet fits any head.
  PoseBlender(const HeadMesh& neutral, PoseSet poses);

  // Writes the deformed head for `values` (only non-zero channels cost time). The outputs
  // are resized only when their size differs, so reused buffers never reallocate.
  void blend(const FapValues& values, Eigen::Matrix3Xf& positions, Eigen::Matrix3Xf& normals) const;

  const PoseSet& poses() const { return poses_; }

 private:
  Eigen::Matrix3Xf neutral_;
  PoseSet poses_;
  std::vector<Eigen::Vector3i> triangles_;  // all sub-meshes
  std::vector<int> weld_;                   // vertex -> first vertex at the same position
  std::vector<int> linearChannels_;         // channel indices with a non-empty pose
  // Per channel, the mean offset of each eyeball's vertices: how a value moves the eye's
  // centre of rotation (zero for channels that do not touch the eye).
  std::array<Eigen::Vector3f, kChannelCount> eyeLeftShift_, eyeRightShift_;
};

}  // namespace lacrima::inline common
