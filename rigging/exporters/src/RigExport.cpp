#include <lacrima/exporters/RigExport.h>

#include <lacrima/common/Diagnostics.h>
#include <lacrima/common/FapTable.h>

#include <algorithm>
#include <cctype>
#include <map>

namespace lacrima::exporters {
namespace {

[[noreturn]] void reject(const std::string& targetPath, const std::string& reason) {
  throw FileError({targetPath, 0, 0}, "cannot export: " + reason);
}

std::string channelLabel(int fap) {
  return "FAP " + std::to_string(fap) + " (" + std::string(fapInfo(fap).name) + ")";
}

// PoseBlender adds value * offset for exactly these motions; every other channel is a rotation,
// a code or a particle count, which a linear vertex pose would misrepresent.
bool hasLinearPose(int fap) {
  const FapMotion motion = fapInfo(fap).motion;
  return motion == FapMotion::Translation || motion == FapMotion::Dilation ||
         motion == FapMotion::Curl;
}

void checkHead(const HeadMesh& head, const std::string& targetPath) {
  const int n = head.vertexCount();
  if (n == 0) reject(targetPath, "the head has no vertices");
  if (head.normals.cols() != n)
    reject(targetPath, "the head has " + std::to_string(head.normals.cols()) + " normals for " +
                           std::to_string(n) + " vertices");
  if (head.uvs.cols() != 0 && head.uvs.cols() != n)
    reject(targetPath, "the head has " + std::to_string(head.uvs.cols()) + " uvs for " +
                           std::to_string(n) + " vertices");
  if (!head.positions.allFinite()) reject(targetPath, "the head has a non-finite position");
  const int materialCount = static_cast<int>(head.materials.size());
  for (const HeadSubmesh& s : head.submeshes) {
    const std::string label = "sub-mesh '" + s.name + "'";
    if (s.firstVertex < 0 || s.vertexCount < 0 || s.firstVertex > n ||
        s.vertexCount > n - s.firstVertex)
      reject(targetPath, label + " covers vertices outside 0.." + std::to_string(n - 1));
    if (s.material < -1 || s.material >= materialCount)
      reject(targetPath, label + " uses material " + std::to_string(s.material) + " of " +
                             std::to_string(materialCount));
    const int end = s.firstVertex + s.vertexCount;
    for (const Eigen::Vector3i& t : s.triangles) {
      // glTF gives each sub-mesh its own vertex range, so a triangle must stay inside it.
      if (t.minCoeff() < s.firstVertex || t.maxCoeff() >= end)
        reject(targetPath, label + " has a triangle outside its vertices " +
                               std::to_string(s.firstVertex) + ".." + std::to_string(end - 1));
    }
  }
  if (head.triangleCount() == 0) reject(targetPath, "the head has no triangles");
}

ExportedPose exportPose(int fap, const VertexPose& pose, int vertexCount,
                        const std::string& targetPath) {
  const std::string label = "the pose of " + channelLabel(fap);
  if (!hasLinearPose(fap))
    reject(targetPath, label + " is not a translation: this channel has no pose");
  if (pose.offsets.cols() != static_cast<Eigen::Index>(pose.vertices.size()))
    reject(targetPath, label + " has " + std::to_string(pose.offsets.cols()) + " offsets for " +
                           std::to_string(pose.vertices.size()) + " vertices");
  if (!pose.offsets.allFinite()) reject(targetPath, label + " has a non-finite offset");
  std::map<int, Eigen::Vector3f> summed;
  for (std::size_t k = 0; k < pose.vertices.size(); ++k) {
    const int v = pose.vertices[k];
    if (v < 0 || v >= vertexCount)
      reject(targetPath, label + " moves vertex " + std::to_string(v) + ", but the head has " +
                             std::to_string(vertexCount) + " vertices");
    auto [it, inserted] = summed.try_emplace(v, Eigen::Vector3f::Zero());
    it->second += pose.offsets.col(static_cast<Eigen::Index>(k));
  }
  ExportedPose result;
  result.fap = fap;
  result.name = exportedPoseName(fap);
  result.offsets.resize(3, static_cast<Eigen::Index>(summed.size()));
  for (const auto& [vertex, offset] : summed) {
    result.offsets.col(static_cast<Eigen::Index>(result.vertices.size())) =
        offset * kExportedPoseValue;
    result.vertices.push_back(vertex);
  }
  return result;
}

// Rotations are not exported, but the .mesh bounds sweep them, so their vertices must exist.
void checkRotationGroup(const RotationGroup& group, const std::string& what, int vertexCount,
                        const std::string& targetPath) {
  for (int v : group.vertices) {
    if (v < 0 || v >= vertexCount)
      reject(targetPath, "the " + what + " rotation group has vertex " + std::to_string(v) +
                             ", but the head has " + std::to_string(vertexCount) + " vertices");
  }
  if (!group.centre.allFinite())
    reject(targetPath, "the " + what + " rotation centre is not finite");
}

}  // namespace

std::string exportedPoseName(int fap) {
  const std::string number = std::to_string(fap);
  return "fap" + std::string(number.size() < 2 ? "0" : "") + number + "_" +
         std::string(fapInfo(fap).name);
}

std::vector<ExportedPose> prepareRigExport(const HeadMesh& head, const PoseSet& poses,
                                           const std::string& targetPath) {
  checkHead(head, targetPath);
  const int n = head.vertexCount();
  checkRotationGroup(poses.eyeLeft, "left eye", n, targetPath);
  checkRotationGroup(poses.eyeRight, "right eye", n, targetPath);
  checkRotationGroup(poses.head, "head", n, targetPath);
  std::vector<ExportedPose> result;
  for (int index = 0; index < kChannelCount; ++index) {
    const VertexPose& pose = poses.poses[static_cast<std::size_t>(index)];
    if (pose.empty()) continue;
    // Checked only when there is a pose to place: a PoseSet with no poses at all (vertexCount 0
    // by default) is a valid, if static, rig for any head.
    if (poses.vertexCount != n)
      reject(targetPath, "the poses were baked for " + std::to_string(poses.vertexCount) +
                             " vertices, but the head has " + std::to_string(n));
    result.push_back(exportPose(fapNumber(index), pose, n, targetPath));
  }
  return result;
}

bool isCorneaMaterial(const HeadMesh& head, int material) {
  if (material < 0 || material >= static_cast<int>(head.materials.size())) return false;
  std::string name = head.materials[static_cast<std::size_t>(material)].name;
  std::transform(name.begin(), name.end(), name.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (name.find("cornea") != std::string::npos) return true;
  return std::any_of(head.submeshes.begin(), head.submeshes.end(), [&](const HeadSubmesh& s) {
    return s.material == material && s.name.starts_with("cornea");
  });
}

}  // namespace lacrima::exporters
