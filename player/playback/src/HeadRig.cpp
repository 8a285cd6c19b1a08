// Loading and rigging a head in memory (HeadRig.h).
#include <lacrima/common/Diagnostics.h>
#include <lacrima/common/MediaFiles.h>
#include <lacrima/playback/HeadRig.h>
#include <lacrima/rigging/DefaultHead.h>
#include <lacrima/rigging/FeaturePointFile.h>
#include <lacrima/rigging/ImportProcess.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <initializer_list>
#include <stdexcept>
#include <string_view>

namespace lacrima::playback {

namespace {

// rigHead, with the mesh's file named in the messages of a feature-point file that does not fit.
std::unique_ptr<HeadRig> rigNamedHead(HeadMesh head, const rigging::FeaturePointFile& fdp,
                                      const rigging::RigOptions& options,
                                      std::string_view meshName) {
  auto rig = std::make_unique<HeadRig>();
  rig->head = std::move(head);
  Warnings warnings;
  rigging::FeaturePointFile points = rigging::validateFeaturePoints(
      fdp, rig->head, &warnings, rigging::FeaturePointSet::Complete, meshName);
  rig->frame = rigging::bringToFaceFrame(rig->head, points, &warnings);
  rigging::dropIgnoredParts(rig->head, points);
  rig->rig = rigging::buildRig(rig->head, points, options);
  // The scene draws a part the file left untextured by its role (UntexturedParts.h).
  for (HeadSubmesh& part : rig->head.submeshes)
    if (const auto role = rig->rig.roles.find(part.name); role != rig->rig.roles.end())
      part.role = role->second;
  for (const Diagnostic& d : warnings) rig->warnings.push_back(d.toString());
  for (const std::string& w : rig->rig.warnings) rig->warnings.push_back(fdp.path + ": " + w);
  try {
    rig->blender = std::make_unique<PoseBlender>(rig->head, rig->rig.poses);
  } catch (const std::invalid_argument& e) {
    throw FileError({fdp.path, 0, 0},
                    std::string("the baked poses do not fit the head: ") + e.what());
  }
  return rig;
}

// Reads the feature-point file at `fdpPath` and rigs `head` (read from `meshName`) with it.
std::unique_ptr<HeadRig> rigHeadFromFile(HeadMesh head, const std::string& fdpPath,
                                         std::string_view meshName,
                                         const rigging::RigOptions& options = {}) {
  Warnings warnings;
  const rigging::FeaturePointFile fdp = rigging::readFeaturePointFile(fdpPath, &warnings);
  auto rig = rigNamedHead(std::move(head), fdp, options, meshName);
  std::vector<std::string> fileWarnings;
  for (const Diagnostic& d : warnings) fileWarnings.push_back(d.toString());
  rig->warnings.insert(rig->warnings.begin(), fileWarnings.begin(), fileWarnings.end());
  return rig;
}

}  // namespace

std::unique_ptr<HeadRig> rigHead(HeadMesh head, const rigging::FeaturePointFile& fdp,
                                 const rigging::RigOptions& options) {
  return rigNamedHead(std::move(head), fdp, options, {});
}

std::unique_ptr<HeadRig> loadDefaultHeadRig() {
  if (!rigging::defaultHeadAvailable())
    throw FileError({rigging::defaultHeadPackageDir(), 0, 0},
                    "the default head is not in the cache; fetch it with " +
                        rigging::defaultHeadFetchCommand() +
                        ", or bring your own with --mesh FILE --fdp FILE");
  return rigHeadFromFile(rigging::loadDefaultHead(), findMediaFile("default-head.fdp.json"),
                         "the default head in " + rigging::defaultHeadPackageDir());
}

std::unique_ptr<HeadRig> loadHeadRig(const std::string& meshPath, const std::string& fdpPath,
                                     const rigging::RigOptions& options) {
  // Shares of the progress: reading a mesh of ~10^5 vertices costs about as much as the rig's
  // first stages, the feature-point file almost nothing.
  constexpr double kMeshRead = 0.25, kPointsRead = 0.3;
  const auto report = [&](double fraction, std::string_view stage) {
    if (options.progress) options.progress(fraction, stage);
  };
  const std::string reading = "reading " + std::filesystem::path(meshPath).filename().string();
  report(0.0, reading);
  // The mesh is a user's file: read by the importer process (ImportProcess.h). While it reads,
  // the progress report is repeated now and then, so that a caller that stops a job by
  // throwing from it (the editor's RigJob) stops the import too.
  rigging::ImportOptions importOptions;
  if (options.progress) {
    auto last = std::chrono::steady_clock::now();
    importOptions.cancelled = [&report, &reading, last]() mutable {
      const auto now = std::chrono::steady_clock::now();
      if (now - last >= std::chrono::milliseconds(100)) {
        last = now;
        report(0.0, reading);
      }
      return false;
    };
  }
  HeadMesh head = rigging::importHeadMeshIsolated(meshPath, importOptions);
  report(kMeshRead, "reading the feature points");
  rigging::RigOptions rest = options;
  if (options.progress)
    rest.progress = [&options](double fraction, std::string_view stage) {
      options.progress(kPointsRead + (1.0 - kPointsRead) * fraction, stage);
    };
  return rigHeadFromFile(std::move(head), fdpPath, meshPath, rest);
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
