// EditorModel's mood layer edits (MoodLayer.h). Every edit is one MoodLayerCommand holding the
// layer and colour curves before and after; adding a layer from constant moods and baking also
// change the mood curves or the keys, in the same undo macro.
#include <lacrima/editing/EditCommands.h>
#include <lacrima/editing/EditorModel.h>
#include <lacrima/editing/MoodGeneration.h>

#include <stdexcept>
#include <string>

namespace lacrima::editing {
namespace {

// `curves` with the script's keys written from `start` on, each mood's old keys within
// [start, end] gone: the constant moods of Generate crying... made editable.
MoodCurves keyedFromScript(MoodCurves curves, const MoodScript& script, double start, double end) {
  std::vector<MoodKey> keys = script.keys();
  if (keys.empty()) keys.push_back({});
  for (Mood mood : kMoods) {
    std::vector<IntensityKey> written;
    for (const IntensityKey& key : curves[mood].keys())
      if (key.time < start - kSameKeyTime || key.time > end + kSameKeyTime) written.push_back(key);
    for (const MoodKey& key : keys)
      if (start + key.time <= end)
        written.push_back({start + key.time, key.levels[mood], Interpolation::Smooth});
    curves[mood] = IntensityCurve(std::move(written));
  }
  return curves;
}

}  // namespace

void EditorModel::applyMoodLayer(const MoodLayerState& state) {
  document_.moodLayer = state.layer;
  document_.colours = state.colours;
  refreshValues();
  emit moodLayerChanged();
  emit valuesChanged();
}

void EditorModel::pushMoodLayer(MoodLayerState after, const QString& text) {
  MoodLayerState before{document_.moodLayer, document_.colours};
  if (after == before) return;
  undo_.push(new MoodLayerCommand(*this, std::move(before), std::move(after), text));
}

void EditorModel::addMoodLayer(const MoodGenerationRequest& request) {
  if (request.seed > MoodLayer::kMaxSeed)
    throw std::invalid_argument("Seed: a layer's seed is a whole number from 0 to " +
                                std::to_string(MoodLayer::kMaxSeed));
  MoodLayer layer;
  layer.seed = request.seed;
  layer.start = request.start;
  layer.end = request.end;
  if (!(layer.start >= 0 && layer.end > layer.start && layer.end <= kMaxMoodSeconds))
    throw std::invalid_argument("expected a time range from 0 to 86400 s, its end after its start");
  const std::string tooLong = bakeLengthProblem(document_.fps, layer.start, layer.end);
  if (!tooLong.empty()) throw std::invalid_argument(tooLong);
  const bool keyMoods = request.curves == nullptr;
  if (keyMoods) undo_.beginMacro(tr("Add crying layer"));
  if (keyMoods)
    editMoods(keyedFromScript(document_.moods, request.script, layer.start, layer.end),
              tr("Key moods"));
  pushMoodLayer({layer, document_.colours}, tr("Add crying layer"));
  if (keyMoods) undo_.endMacro();
}

void EditorModel::setMoodLayerMuted(bool muted) {
  if (!document_.moodLayer) return;
  MoodLayerState after{document_.moodLayer, document_.colours};
  after.layer->muted = muted;
  pushMoodLayer(std::move(after), muted ? tr("Mute crying layer") : tr("Unmute crying layer"));
}

void EditorModel::setMoodLayerSeed(std::uint64_t seed) {
  if (!document_.moodLayer) return;
  if (seed > MoodLayer::kMaxSeed) {
    emit message(tr("A layer's seed is a whole number from 0 to %1").arg(MoodLayer::kMaxSeed));
    return;
  }
  MoodLayerState after{document_.moodLayer, document_.colours};
  after.layer->seed = seed;
  pushMoodLayer(std::move(after), tr("Seed crying layer"));
}

void EditorModel::removeMoodLayer() {
  pushMoodLayer({std::nullopt, document_.colours}, tr("Delete crying layer"));
}

void EditorModel::bakeMoodLayer() {
  if (!document_.moodLayer) return;
  const MoodLayer& layer = *document_.moodLayer;
  if (layer.muted) {
    emit message(tr("The crying layer is muted: unmute it to bake what it adds"));
    return;
  }
  MoodGenerationRequest request;
  request.start = layer.start;
  request.end = layer.end;
  request.curves = &document_.moods;
  request.seed = layer.seed;
  request.fps = document_.fps;
  request.addToKeys = true;
  MoodGenerationPlan plan;
  FaceColourCurves colours;
  try {
    plan = planMoodGeneration(document_.keys, request);
    const MoodLayerTake* take = moodTake();
    if (!take) return;
    colours = bakeMoodColours(document_.colours, *take);
  } catch (const std::invalid_argument& e) {  // a rate chosen since makes it too long
    emit message(tr("Cannot bake the crying layer: %1").arg(QString::fromUtf8(e.what())));
    return;
  }
  undo_.beginMacro(tr("Bake crying layer to keys"));
  pushKeyEdit(plan.change, tr("Bake crying layer to keys"), std::nullopt);
  pushMoodLayer({std::nullopt, std::move(colours)}, tr("Bake crying layer to keys"));
  undo_.endMacro();
}

}  // namespace lacrima::editing
