#pragma once
// Opening what the player plays: a .fap file (FapReader, tolerant) or a Lacrima project
// (ProjectDocument, baked at its frame rate, with its scene settings and tear sources).
// A path ending in .json or .lacrima (any case) is a project, anything else a FAP file, the
// rule lacrima-fap uses.
#include <lacrima/common/Diagnostics.h>
#include <lacrima/common/FapAnimation.h>
#include <lacrima/common/ProjectDocument.h>

#include <memory>
#include <string>

namespace lacrima::playback {

struct AnimationFile {
  FapAnimation animation;
  bool project = false;
  SceneSettings scene;       // the project's; defaults for a FAP file
  TearSources tearSources;   // the project's; rig defaults for a FAP file
  FaceColourCurves colours;  // the project's keyed colours; none for a FAP file
  double startTime = 0;      // the project time of frame 0 (where its colours are read from)
  Warnings warnings;         // the FAP reader's (gaps filled, odd header, ...)
  // The project's mood layer, whose colours replace the keyed ones within its range.
  std::shared_ptr<const MoodLayerTake> moodTake;
};

// Throws FileError naming the file, the line (and column or JSON path) and what was expected,
// also for a file that decodes to no frames at all.
AnimationFile readAnimationFile(const std::string& path);

}  // namespace lacrima::playback
