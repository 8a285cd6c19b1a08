// Loading and rigging a head in memory (HeadRig.h).
#include <lacrima/common/Diagnostics.h>
#include <lacrima/common/MediaFiles.h>
#include <lacrima/playback/HeadRig.h>
#include <lacrima/rigging/DefaultHead.h>
#include <lacrima/rigging/FeaturePointFile.h>
#include <lacrima/rigging/MeshImport.h>

#include <algorithm>
#include <initializer_list>
#include <stdexcept>
#include <string_view>

namespace lacrima::playback {

namespace {

// Binds the feature points, bakes the poses and builds the blender for `rig->head`.
void rigHead(HeadRig& rig, const std::string& fdpPath) {
  Warnings warnings;
  const rigging::FeaturePointFile fdp = rigging::readFeaturePointFile(fdpPath, &warnings);
  rigging::validateFeaturePoints(fdp, rig.head, &warnings);
  rig.rig = rigging::buildRig(rig.head, fdp);
  for (const Diagnostic& d : warnings) rig.warnings.push_back(d.toString());
  for (const std::string& w : rig.rig.warnings) rig.warnings.push_back(fdpPath + ": " + w);
  try {
    rig.blender = std::make_unique<PoseBlender>(rig.head, rig.rig.poses);
  } catch (const std::invalid_argument& e) {
    throw FileError({fdpPath, 0, 0},
                    std::string("the baked poses do not fit the head: ") + e.what());
  }
}

}  // namespace

std::unique_ptr<HeadRig> loadDefaultHeadRig() {
  if (!rigging::defaultHeadAvailable())
    throw FileError(
        {rigging::defaultHeadPackageDir(), 0, 0},
        "the default head is not in the cache; fetch it with packaging/fetch-default-head.sh "
        "(packaging/lacrima.sh does), or bring your own with --mesh FILE --fdp FILE");
  auto rig = std::make_unique<HeadRig>();
  rig->head = rigging::loadDefaultHead();
  rigHead(*rig, findMediaFile("default-head.fdp.json"));
  return rig;
}

std::unique_ptr<HeadRig> loadHeadRig(const std::string& meshPath, const std::string& fdpPath) {
  auto rig = std::make_unique<HeadRig>();
  try {
    rig->head = rigging::importHeadMesh(meshPath);
  } catch (const FileError&) {
    throw;
  } catch (const std::runtime_error& e) {
    // importHeadMesh's message already names the file; keep it as the location for dialogs.
    throw FileError({meshPath, 0, 0}, e.what());
  }
  rigHead(*rig, fdpPath);
  return rig;
}

namespace {

std::vector<Eigen::Vector3i> trianglesWithRole(const HeadRig& rig,
                                               std::initializer_list<std::string_view> wanted) {
  std::vector<Eigen::Vector3i> triangles;
  for (const HeadSubmesh& s : rig.head.submeshes) {
    const auto role = rig.rig.roles.find(s.name);
    if (role == rig.rig.roles.end()) continue;
    if (std::find(wanted.begin(), wanted.end(), std::string_view(role->second)) != wanted.end())
      triangles.insert(triangles.end(), s.triangles.begin(), s.triangles.end());
  }
  return triangles;
}

}  // namespace

std::vector<Eigen::Vector3i> skinTriangles(const HeadRig& rig) {
  return trianglesWithRole(rig, {"skin"});
}

std::vector<Eigen::Vector3i> eyeTriangles(const HeadRig& rig) {
  return trianglesWithRole(rig, {"eye_left", "eye_right"});
}

}  // namespace lacrima::playback
