#pragma once
// What the .mesh and .glb exporters share: how an exported pose is named and scaled, and the
// checks a head and its poses must pass before anything is written.
//
// Exported poses hold the offsets for a FAP value of kExportedPoseValue = 1024, i.e. one X0 of
// the channel's FAPU (FAPU = X0 / 1024), instead of PoseSet's value of 1. A pose weight in
// OGRE or a morph-target weight in glTF is therefore value / 1024, a jaw opened by 512 has
// weight 0.5, and the stored offsets have the size of a real facial motion (a centimetre or
// so on a real head) rather than 1/1024 of it, which keeps them clear of the round-off of
// tools that quantise or print morph targets.
#include <lacrima/common/HeadMesh.h>
#include <lacrima/common/PoseSet.h>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace lacrima::exporters {

inline constexpr float kExportedPoseValue = 1024.0f;

// "fapNN_name" with a two-digit number: exportedPoseName(3) == "fap03_open_jaw".
std::string exportedPoseName(int fap);

// One pose as it is written: vertices ascending and unique (repeated entries of the input are
// summed, as PoseBlender would add them), offsets already multiplied by kExportedPoseValue.
struct ExportedPose {
  int fap = 0;
  std::string name;
  std::vector<int> vertices;
  Eigen::Matrix3Xf offsets;  // 3 x vertices.size()
};

// Checks `head` and `poses` and returns the poses to export, in channel order: every non-empty
// pose of a channel that moves vertices linearly (translations, eyeball thrust included, pupil
// dilation, tongue roll).
// Throws FileError naming `targetPath` with the reason when the head has no triangles, a
// sub-mesh range, triangle, material or array size is inconsistent, a pose was baked for a
// different vertex count, touches a vertex that does not exist, holds a non-finite offset, or
// sits on a channel that cannot have a pose (head/eye rotations, high-level FAPs, tears), or a
// rotation group names a vertex that does not exist.
std::vector<ExportedPose> prepareRigExport(const HeadMesh& head, const PoseSet& poses,
                                           const std::string& targetPath);

// Whether material `material` is a cornea: named so, or worn by a sub-mesh whose role starts
// with "cornea". Both exporters make it a glossy, see-through layer, else the eyes look black.
bool isCorneaMaterial(const HeadMesh& head, int material);

}  // namespace lacrima::exporters
