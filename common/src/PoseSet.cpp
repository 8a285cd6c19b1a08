#include <lacrima/common/PoseSet.h>

#include <lacrima/common/FapTable.h>
#include <lacrima/common/Fapu.h>
#include <lacrima/common/HeadTurns.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>

namespace lacrima::inline common {
namespace {

bool anyNonZero(const FapValues& values, std::initializer_list<int> faps) {
  for (int fap : faps)
    if (usableFapValue(values[channelIndex(fap)]) != 0.0f) return true;
  return false;
}

// p <- R (p - c) + c for the group's vertices, written as R p + t with t = c - R c.
void rotateVertices(Eigen::Matrix3Xf& positions, const std::vector<int>& vertices,
                    const Eigen::Matrix3f& rotation, const Eigen::Vector3f& centre) {
  const Eigen::Vector3f shift = centre - rotation * centre;
  for (int v : vertices) {
    const Eigen::Vector3f p = positions.col(v);
    positions.col(v) = rotation * p + shift;
  }
}

void requireVertex(int v, int vertexCount, const std::string& where) {
  if (v < 0 || v >= vertexCount)
    throw std::invalid_argument("PoseBlender: " + where + " names vertex " + std::to_string(v) +
                                " of a head with " + std::to_string(vertexCount) + " vertices");
}

void validateGroup(const RotationGroup& group, int vertexCount, const char* name) {
  for (int v : group.vertices) requireVertex(v, vertexCount, std::string(name) + " rotation group");
  if (!group.vertices.empty() && !group.centre.allFinite())
    throw std::invalid_argument(std::string("PoseBlender: the ") + name +
                                " rotation group's centre is not finite");
}

// The mean offset per unit value of the group's vertices under `pose`, given a per-vertex
// membership flag for the group.
Eigen::Vector3f meanShift(const VertexPose& pose, const std::vector<char>& member,
                          std::size_t groupSize) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (std::size_t k = 0; k < pose.vertices.size(); ++k)
    if (member[static_cast<std::size_t>(pose.vertices[k])])
      sum += pose.offsets.col(static_cast<Eigen::Index>(k)).cast<double>();
  return groupSize ? Eigen::Vector3f((sum / double(groupSize)).cast<float>())
                   : Eigen::Vector3f::Zero();
}

std::vector<char> membership(const RotationGroup& group, int vertexCount) {
  std::vector<char> member(static_cast<std::size_t>(vertexCount), 0);
  for (int v : group.vertices) member[static_cast<std::size_t>(v)] = 1;
  return member;
}

}  // namespace

ChannelMask PoseSet::drivenChannels() const {
  ChannelMask mask;
  for (int i = 0; i < kChannelCount; ++i)
    if (!poses[static_cast<std::size_t>(i)].empty()) mask.set(static_cast<std::size_t>(i));
  auto setFaps = [&](std::initializer_list<int> faps) {
    for (int fap : faps) mask.set(static_cast<std::size_t>(channelIndex(fap)));
  };
  if (!eyeLeft.vertices.empty()) setFaps({23, 25});
  if (!eyeRight.vertices.empty()) setFaps({24, 26});
  if (!head.vertices.empty()) setFaps({48, 49, 50});
  return mask;
}

PoseBlender::PoseBlender(const HeadMesh& neutral, PoseSet poses)
    : neutral_(neutral.positions), poses_(std::move(poses)) {
  const int n = static_cast<int>(neutral_.cols());
  if (poses_.vertexCount == 0 && poses_.drivenChannels().none()) poses_.vertexCount = n;
  if (poses_.vertexCount != n)
    throw std::invalid_argument("PoseBlender: the poses were baked for " +
                                std::to_string(poses_.vertexCount) + " vertices, the head has " +
                                std::to_string(n));

  for (int i = 0; i < kChannelCount; ++i) {
    const VertexPose& pose = poses_.poses[static_cast<std::size_t>(i)];
    const std::string where = "the pose of FAP " + std::to_string(fapNumber(i));
    if (pose.offsets.cols() != static_cast<Eigen::Index>(pose.vertices.size()))
      throw std::invalid_argument("PoseBlender: " + where + " has " +
                                  std::to_string(pose.vertices.size()) + " vertices but " +
                                  std::to_string(pose.offsets.cols()) + " offsets");
    for (int v : pose.vertices) requireVertex(v, n, where);
    if (!pose.offsets.allFinite())
      throw std::invalid_argument("PoseBlender: " + where + " has non-finite offsets");
    if (!pose.empty()) linearChannels_.push_back(i);
  }
  validateGroup(poses_.eyeLeft, n, "left eye");
  validateGroup(poses_.eyeRight, n, "right eye");
  validateGroup(poses_.head, n, "head");

  triangles_.reserve(static_cast<std::size_t>(neutral.triangleCount()));
  for (const HeadSubmesh& s : neutral.submeshes)
    for (const Eigen::Vector3i& t : s.triangles) {
      for (int k = 0; k < 3; ++k) requireVertex(t[k], n, "a triangle of sub-mesh '" + s.name + "'");
      triangles_.push_back(t);
    }
  weld_ = weldCoincidentVertices(neutral_);

  // Precomputed once so that a frame moves each eye's centre with O(channels) work instead of
  // a pass over the eyeball.
  const std::vector<char> left = membership(poses_.eyeLeft, n);
  const std::vector<char> right = membership(poses_.eyeRight, n);
  eyeLeftShift_.fill(Eigen::Vector3f::Zero());
  eyeRightShift_.fill(Eigen::Vector3f::Zero());
  for (int i : linearChannels_) {
    const VertexPose& pose = poses_.poses[static_cast<std::size_t>(i)];
    eyeLeftShift_[static_cast<std::size_t>(i)] =
        meanShift(pose, left, poses_.eyeLeft.vertices.size());
    eyeRightShift_[static_cast<std::size_t>(i)] =
        meanShift(pose, right, poses_.eyeRight.vertices.size());
  }
}

void PoseBlender::blend(const FapValues& values, Eigen::Matrix3Xf& positions,
                        Eigen::Matrix3Xf& normals) const {
  positions = neutral_;  // same-size assignment copies without reallocating

  // Sum of value_i * d_i over the channels in use. The scatter through vertex indices cannot
  // be vectorised across vertices, so it is a plain loop over contiguous xyz triples.
  Eigen::Vector3f leftCentre = poses_.eyeLeft.centre;
  Eigen::Vector3f rightCentre = poses_.eyeRight.centre;
  float* out = positions.data();
  for (int i : linearChannels_) {
    const float value = usableFapValue(values[static_cast<std::size_t>(i)]);
    if (value == 0.0f) continue;
    const VertexPose& pose = poses_.poses[static_cast<std::size_t>(i)];
    const float* offset = pose.offsets.data();
    for (int v : pose.vertices) {
      float* p = out + 3 * static_cast<std::ptrdiff_t>(v);
      p[0] += value * offset[0];
      p[1] += value * offset[1];
      p[2] += value * offset[2];
      offset += 3;
    }
    leftCentre += value * eyeLeftShift_[static_cast<std::size_t>(i)];
    rightCentre += value * eyeRightShift_[static_cast<std::size_t>(i)];
  }

  // Eyeballs: yaw, then pitch about the yawed horizontal axis (E = R_yaw * R_pitch).
  auto turnEye = [&](const RotationGroup& eye, EyeSide side, int yawFap, int pitchFap,
                     const Eigen::Vector3f& centre) {
    if (eye.vertices.empty() || !anyNonZero(values, {yawFap, pitchFap})) return;
    rotateVertices(positions, eye.vertices, eyeTurn(values, side).toRotationMatrix().cast<float>(),
                   centre);
  };
  turnEye(poses_.eyeLeft, EyeSide::Left, 23, 25, leftCentre);
  turnEye(poses_.eyeRight, EyeSide::Right, 24, 26, rightCentre);

  // Head: R_head = R_yaw(49) * R_pitch(48) * R_roll(50) about the neck pivot.
  if (!poses_.head.vertices.empty() && anyNonZero(values, {48, 49, 50})) {
    const Eigen::Quaterniond turn = headTurn(values);
    rotateVertices(positions, poses_.head.vertices, turn.toRotationMatrix().cast<float>(),
                   poses_.head.centre);
  }

  accumulateNormals(positions, triangles_, weld_, normals);
}

}  // namespace lacrima::inline common
