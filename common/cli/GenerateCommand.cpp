#include "GenerateCommand.h"

#include "CliFiles.h"

#include <lacrima/common/mood/MoodGenerator.h>

#include <charconv>
#include <stdexcept>

namespace lacrima {
namespace {

// Colours change slowly: a key per frame would make a ten-minute project's colours 26,000 keys
// of JSON for nothing. A key every kColourStep seconds, linear between, keeps them within a
// hundredth of the generated values.
constexpr double kColourStep = 0.25;

std::vector<IntensityKey> colourKeys(const MoodTake& take, double FaceColours::*colour) {
  std::vector<IntensityKey> keys;
  const double fps = take.animation.fps;
  const int every = std::max(1, static_cast<int>(kColourStep * fps));
  const int last = static_cast<int>(take.colours.size()) - 1;
  for (int i = 0; i <= last; i += every) {
    keys.push_back(
        {i / fps, take.colours[static_cast<std::size_t>(i)].*colour, Interpolation::Linear});
    if (i < last && i + every > last) i = last - every;  // always key the last frame
  }
  return keys;
}

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
    project.colours.redness = IntensityCurve(colourKeys(take, &FaceColours::redness));
    project.colours.blush = IntensityCurve(colourKeys(take, &FaceColours::blush));
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
