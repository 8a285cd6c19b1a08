#include <lacrima/player/ProjectHead.h>

#include <lacrima/common/ProjectPath.h>
#include <lacrima/playback/AnimationFile.h>

namespace lacrima::player {

std::optional<HeadFiles> headOfFile(const std::string& path) {
  if (!isProjectPath(path)) return std::nullopt;
  return ProjectDocument::load(path).head;
}

std::unique_ptr<playback::HeadRig> loadHeadFor(const std::optional<HeadFiles>& head,
                                               const std::string& namedBy) {
  if (!head) return playback::loadDefaultHeadRig();
  ProjectDocument probe;
  probe.head = head;
  if (auto missing = probe.missingHeadFile(namedBy)) throw FileError(*missing);
  return playback::loadHeadRig(head->mesh, head->fdp);
}

}  // namespace lacrima::player
