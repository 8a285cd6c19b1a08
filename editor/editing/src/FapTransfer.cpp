#include <lacrima/editing/FapTransfer.h>

#include <lacrima/common/FapReader.h>
#include <lacrima/common/FapWriter.h>
#include <lacrima/editing/KeyReduction.h>

#include <QFileInfo>

#include <cmath>

namespace lacrima::editing {

FapImportResult importAnimation(const FapAnimation& animation, const FapImportOptions& options) {
  FapImportResult result;
  result.frames = animation.frameCount();
  const KeyframeSequence all = KeyframeSequence::fromAnimation(animation, Interpolation::Linear);
  std::vector<Keyframe> keys;
  if (options.reductionTolerance) {
    const std::vector<int> kept = reduceKeyFrames(animation, *options.reductionTolerance);
    result.maxError = reductionError(animation, kept);
    keys.reserve(kept.size());
    for (int index : kept) keys.push_back(all.keys()[static_cast<std::size_t>(index)]);
  } else {
    keys = all.keys();
  }
  result.keys = static_cast<int>(keys.size());
  result.document.name = animation.name;
  result.document.fps = animation.fps;
  result.document.defaultInterpolation = Interpolation::Linear;
  result.document.keys = KeyframeSequence(std::move(keys));
  return result;
}

FapImportResult importFap(const std::string& path, const FapImportOptions& options) {
  FapReadResult read = FapReader::readFile(path);
  FapImportResult result = importAnimation(read.animation, options);
  result.warnings = std::move(read.warnings);
  // A header name of "lacrima" or similar says little; the file's name is what the user knows.
  const std::string base = QFileInfo(QString::fromStdString(path)).completeBaseName().toStdString();
  if (!base.empty()) result.document.name = base;
  return result;
}

FapExportResult exportFap(const ProjectDocument& document, const std::string& path,
                          const FapExportOptions& options) {
  if (!std::isfinite(options.fps) || options.fps <= 0.0)
    throw FileError({path, 0, 0},
                    "export frame rate must be > 0, got " + std::to_string(options.fps));
  if (document.keys.empty())
    throw FileError({path, 0, 0},
                    "nothing to export: the project has no keys yet (press K to add one)");
  const auto [start, end] = document.bakeRange();
  if (const std::string problem = bakeLengthProblem(options.fps, start, end); !problem.empty())
    throw FileError({path, 0, 0}, problem);
  FapAnimation animation = document.bake(options.fps);
  FapExportResult result;
  result.frames = animation.frameCount();
  result.wroteTears = !options.strict && animation.hasTears();
  FapWriter::save(animation, path, FapWriteOptions{options.strict}, &result.warnings);
  return result;
}

}  // namespace lacrima::editing
