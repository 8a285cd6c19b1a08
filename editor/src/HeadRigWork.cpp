#include <lacrima/editor/HeadRigWork.h>

#include <lacrima/playback/HeadRig.h>
#include <lacrima/rigging/RigBuilder.h>

namespace lacrima::editor {

RigJob::Work defaultHeadWork() {
  return [](const auto& progress) {
    progress(0.0, "reading the default head");
    return playback::loadDefaultHeadRig();
  };
}

RigJob::Work headFilesWork(std::string meshPath, std::string fdpPath) {
  return [meshPath = std::move(meshPath), fdpPath = std::move(fdpPath)](const auto& progress) {
    rigging::RigOptions options;
    options.progress = progress;
    return playback::loadHeadRig(meshPath, fdpPath, options);
  };
}

RigJob::Work failingWork(Diagnostic problem) {
  return [problem = std::move(problem)](const auto&) -> std::unique_ptr<playback::HeadRig> {
    throw FileError(problem);
  };
}

}  // namespace lacrima::editor
