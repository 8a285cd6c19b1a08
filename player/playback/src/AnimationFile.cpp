// Reading a FAP file or a project for playback (AnimationFile.h).
#include <lacrima/common/FapReader.h>
#include <lacrima/common/ProjectPath.h>
#include <lacrima/playback/AnimationFile.h>
#include <lacrima/playback/TearQualityOptions.h>

#include <exception>
#include <new>

namespace lacrima::playback {

AnimationFile readAnimationFile(const std::string& path) try {
  AnimationFile file;
  if (isProjectPath(path)) {
    const TearMethodKeys methods = tearMethodKeys();
    const ProjectDocument document =
        ProjectDocument::load(path, ProjectDocument::Use::Bake, &methods);
    file.project = true;
    MoodLayerCache mood;
    file.animation = document.bake(document.fps, mood);
    file.moodTake = mood.shared();
    file.scene = document.scene;
    file.tearSources = document.tearSources;
    file.colours = document.colours;
    file.startTime = document.bakeRange().first;
    if (file.animation.frames.empty())
      throw FileError({path, 0, 0},
                      "the project has no keys, so nothing to play; expected at least one key");
  } else {
    FapReadResult read = FapReader::readFile(path);
    file.animation = std::move(read.animation);
    file.warnings = std::move(read.warnings);
    if (file.animation.frames.empty())
      throw FileError({path, 0, 0},
                      "the file holds no frames; expected at least one mask and value line");
  }
  return file;
} catch (const FileError&) {
  throw;
} catch (const std::bad_alloc&) {
  throw FileError({path, 0, 0}, "not enough memory to read it");
} catch (const std::exception& e) {
  // The readers refuse what they can name a place for; anything else still names the file.
  throw FileError({path, 0, 0}, e.what());
}

}  // namespace lacrima::playback
