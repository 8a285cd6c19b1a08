#include "GenerateCommand.h"

#include "CliFiles.h"

#include <lacrima/common/mood/MoodLayer.h>

#include <charconv>
#include <stdexcept>

namespace lacrima {
namespace {

std::string formatNumber(double value) {
  char buf[32];
  auto [end, ec] = std::to_chars(buf, buf + sizeof buf, value);
  return ec == std::errc() ? std::string(buf, end) : std::to_string(value);
}

}  // namespace

std::string generate(const GenerateRequest& request) {
  const MoodScript script = request.script
                                ? MoodScript::load(*request.script)
                                : MoodScript::constant(request.moods.value_or(MoodLevels{}));
  MoodTake take;
  try {
    take = generateMoodTake(script, request.seed, request.seconds, request.fps);
  } catch (const std::invalid_argument& error) {
    throw std::invalid_argument(request.output + ": " + error.what());
  }
  take.animation.name = "mood";
  if (isProjectPath(request.output)) {
    ProjectDocument project = ProjectDocument::fromAnimation(take.animation);
    project.colours.redness = IntensityCurve(moodColourKeys(take, &FaceColours::redness));
    project.colours.blush = IntensityCurve(moodColourKeys(take, &FaceColours::blush));
    project.scene.blush = true;  // the generated blush is shown (FaceColours.h)
    const std::string json = project.toJson();
    if (static_cast<long long>(json.size()) > ProjectDocument::kMaxFileBytes)
      throw std::invalid_argument(
          request.output + ": the project would be " + std::to_string(json.size() >> 20) +
          " MiB, more than the " + std::to_string(ProjectDocument::kMaxFileBytes >> 20) +
          " MiB a project may be; write a .fap file, or shorten it or lower --rate");
    project.save(request.output);
  } else {
    saveAnimation(take.animation, request.output, request.strict);
  }
  return request.output + ": " + std::to_string(take.animation.frameCount()) + " frames at " +
         formatNumber(request.fps) + " fps, moods " +
         (request.script ? *request.script : toString(request.moods.value_or(MoodLevels{}))) +
         ", seed " + std::to_string(request.seed);
}

}  // namespace lacrima
