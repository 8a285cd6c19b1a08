#include <lacrima/export/ExportOptions.h>

#include <cmath>
#include <string>

namespace lacrima::exporting {

FrameSpan openForExport(playback::Playback& playback, const ExportOptions& options) {
  playback.setSimulationThreads(options.threads);
  playback.open(options.input);
  if (!options.tears) playback.removeTears();
  if (options.quality) {
    SceneSettings scene = playback.scene();
    scene.quality.level = *options.quality;
    playback.setScene(scene);
  }
  const int frames = playback.frameCount();
  const FrameSpan span{options.firstFrame, options.lastFrame < 0 ? frames - 1 : options.lastFrame};
  if (span.first < 0 || span.first > span.last || span.last >= frames)
    throw std::invalid_argument("cannot export frames " + std::to_string(span.first) + " to " +
                                std::to_string(span.last) + ": the animation has frames 0 to " +
                                std::to_string(frames - 1));
  return span;
}

double metresPerUnit(const playback::HeadRig& rig) {
  const double es0 = rig.rig.fapu.es0;
  return std::isfinite(es0) && es0 > 0 ? kMeanEyeSeparationMetres / es0 : 1.0;
}

void reportProgress(const ExportOptions& options, const playback::Playback& playback, int done,
                    int total) {
  if (options.frameShown) options.frameShown(playback);
  if (options.progress && !options.progress(done, total)) throw ExportCancelled();
}

}  // namespace lacrima::exporting
