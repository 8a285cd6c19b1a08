#include <lacrima/editor/HeadRigWork.h>

#include <lacrima/playback/HeadRig.h>
#include <lacrima/rigging/FeaturePointFile.h>
#include <lacrima/rigging/MeshImport.h>

#include <filesystem>
#include <stdexcept>

namespace lacrima::editor {

namespace {

// Shares of the progress bar: reading a mesh of ~10^5 vertices costs about as much as the
// rig's first stages, the feature-point file almost nothing.
constexpr double kMeshRead = 0.25;
constexpr double kPointsRead = 0.3;

}  // namespace

RigJob::Work defaultHeadWork() {
  return [](const auto& progress) {
    progress(0.0, "reading the default head");
    return playback::loadDefaultHeadRig();
  };
}

RigJob::Work headFilesWork(std::string meshPath, std::string fdpPath) {
  return [meshPath = std::move(meshPath), fdpPath = std::move(fdpPath)](const auto& progress) {
    progress(0.0, "reading " + std::filesystem::path(meshPath).filename().string());
    HeadMesh head;
    try {
      head = rigging::importHeadMesh(meshPath);
    } catch (const FileError&) {
      throw;
    } catch (const std::runtime_error& e) {
      throw FileError({meshPath, 0, 0}, e.what());  // the message names the file already
    }
    progress(kMeshRead, "reading the feature points");
    Warnings fileWarnings;
    const rigging::FeaturePointFile points = rigging::readFeaturePointFile(fdpPath, &fileWarnings);
    rigging::RigOptions options;
    options.progress = [&progress](double fraction, std::string_view stage) {
      progress(kPointsRead + (1.0 - kPointsRead) * fraction, stage);
    };
    auto rig = playback::rigHead(std::move(head), points, options);
    std::vector<std::string> lines;
    for (const Diagnostic& d : fileWarnings) lines.push_back(d.toString());
    rig->warnings.insert(rig->warnings.begin(), lines.begin(), lines.end());
    return rig;
  };
}

RigJob::Work failingWork(Diagnostic problem) {
  return [problem = std::move(problem)](const auto&) -> std::unique_ptr<playback::HeadRig> {
    throw FileError(problem);
  };
}

}  // namespace lacrima::editor
