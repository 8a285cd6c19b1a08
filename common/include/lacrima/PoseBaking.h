#pragma once
// Pose baking: from feature-point influence weights to one pose per FAP.
//
// For translational FAP i with feature point p, unit u and direction dir_i:
//   d_{i,v} = w_p(v) * unitValue(u) * dir_i
// so a value of 1024 moves p (weight 1) by its FAPU distance X0. Pupil dilation (29, 30) and
// tongue roll (47) have dedicated poses (see bakePoses); eyeball and head rotations become
// RotationGroups. High-level FAPs and tear channels have no pose.
#include <lacrima/Fapu.h>
#include <lacrima/HeadMesh.h>
#include <lacrima/PoseSet.h>

#include <map>
#include <string>
#include <vector>

namespace lacrima {

// Sparse weights of one feature point: vertices[k] has weight weights[k] in (0, 1].
struct FeaturePointInfluence {
  std::vector<int> vertices;
  std::vector<float> weights;
};

struct RigInput {
  const HeadMesh* mesh = nullptr;
  FapuSet fapu;
  std::map<std::string, FeaturePointInfluence> influences;  // by FDP id, e.g. "2.1"
  std::map<std::string, Eigen::Vector3f> featurePoints;     // neutral positions by FDP id
  RotationGroup eyeLeft, eyeRight;  // vertices of each eyeball (+cornea), centre of rotation
  Eigen::Vector3f neckPivot = Eigen::Vector3f::Zero();
  std::vector<int> headVertices;    // vertices that follow head rotation (default: all)
};

struct PoseBakeReport {
  std::vector<int> bakedFaps;                    // FAPs that got a pose or rotation group
  std::vector<std::string> warnings;             // e.g. "FAP 29: no pupil geometry; pose empty"
};

PoseSet bakePoses(const RigInput& input, PoseBakeReport* report = nullptr);

}  // namespace lacrima
