// EditorModel's layer edits (presets applied as layers; PoseLayer.h). Every edit is one
// LayersCommand holding the layer list before and after.
#include <lacrima/common/FapTable.h>
#include <lacrima/editing/EditCommands.h>
#include <lacrima/editing/EditorModel.h>
#include <lacrima/editing/IntensityKeyEdits.h>
#include <lacrima/editing/KeyChange.h>
#include <lacrima/editing/PresetLibrary.h>

#include <algorithm>
#include <cmath>

namespace lacrima::editing {
namespace {

// How long a layer takes to rise to its intensity when applied: long enough to read as a
// change of expression, short enough to land on the beat the animator chose.
constexpr double kLayerRampSeconds = 0.5;

// An intensity scales a whole pose; the file format refuses beyond +-100 (ProjectKeysJson).
constexpr double kMaxLayerIntensity = 100.0;

// "Sob", or "Sob 2" when a layer is already called "Sob".
std::string uniqueLayerName(const std::vector<PoseLayer>& layers, const std::string& base) {
  const auto taken = [&](const std::string& name) {
    return std::any_of(layers.begin(), layers.end(),
                       [&](const PoseLayer& layer) { return layer.name == name; });
  };
  if (!taken(base)) return base;
  for (int n = 2;; ++n) {
    const std::string candidate = base + " " + std::to_string(n);
    if (!taken(candidate)) return candidate;
  }
}

}  // namespace

void EditorModel::pushLayers(std::vector<PoseLayer> after, const QString& text) {
  if (after == document_.layers) return;
  undo_.push(new LayersCommand(*this, document_.layers, std::move(after), text));
}

void EditorModel::applyLayers(const std::vector<PoseLayer>& layers) {
  document_.layers = layers;
  refreshValues();
  emit layersChanged();
  emit valuesChanged();
}

void EditorModel::applyPresetAsLayer(const Preset& preset, double intensity) {
  if (preset.keys.empty()) return;
  if (preset.isSequence()) {
    emit message(tr("%1 is a sequence of poses; only a single pose can be a layer, so apply it "
                    "as keys.")
                     .arg(QString::fromStdString(preset.name)));
    return;
  }
  intensity = std::clamp(std::isfinite(intensity) ? intensity : 1.0, 0.0, 2.0);
  PoseLayer layer;
  layer.name = uniqueLayerName(document_.layers, preset.name);
  const Keyframe& pose = preset.keys.front();
  for (int fap = 1; fap <= kChannelCount; ++fap) {
    if (pose.has(fap) && !isHighLevelFap(fap)) layer.setPoseValue(fap, pose.value(fap));
  }
  if (layer.channels().none()) {
    emit message(tr("%1 only names viseme or expression codes, which do not mix as a layer.")
                     .arg(QString::fromStdString(preset.name)));
    return;
  }
  std::vector<IntensityKey> keys;
  const double rampStart = snapTime(time_ - kLayerRampSeconds);
  if (time_ - rampStart > kSameKeyTime) keys.push_back({rampStart, 0.0, Interpolation::Smooth});
  keys.push_back({time_, intensity, Interpolation::Smooth});
  layer.setIntensityKeys(std::move(keys));
  std::vector<PoseLayer> after = document_.layers;
  after.push_back(std::move(layer));
  pushLayers(std::move(after), tr("Add layer %1").arg(QString::fromStdString(preset.name)));
}

void EditorModel::setLayerMuted(int index, bool muted) {
  if (index < 0 || index >= static_cast<int>(document_.layers.size())) return;
  std::vector<PoseLayer> after = document_.layers;
  after[static_cast<std::size_t>(index)].muted = muted;
  pushLayers(std::move(after), muted ? tr("Mute layer") : tr("Unmute layer"));
}

void EditorModel::removeLayer(int index) {
  if (index < 0 || index >= static_cast<int>(document_.layers.size())) return;
  std::vector<PoseLayer> after = document_.layers;
  const QString name = QString::fromStdString(after[static_cast<std::size_t>(index)].name);
  after.erase(after.begin() + index);
  pushLayers(std::move(after), tr("Delete layer %1").arg(name));
}

void EditorModel::keyLayerIntensity(int index, double value) {
  if (index < 0 || index >= static_cast<int>(document_.layers.size())) return;
  if (!std::isfinite(value) || std::abs(value) > kMaxLayerIntensity) {
    emit message(tr("Layer intensity must lie within -%1..%1").arg(kMaxLayerIntensity));
    return;
  }
  std::vector<PoseLayer> after = document_.layers;
  PoseLayer& layer = after[static_cast<std::size_t>(index)];
  layer.setIntensityKeys(withKeyAt(layer.intensityKeys(), time_, value));
  pushLayers(std::move(after), tr("Key layer intensity"));
}

void EditorModel::unkeyLayerIntensity(int index) {
  if (index < 0 || index >= static_cast<int>(document_.layers.size())) return;
  std::vector<PoseLayer> after = document_.layers;
  PoseLayer& layer = after[static_cast<std::size_t>(index)];
  layer.setIntensityKeys(withoutKeyAt(layer.intensityKeys(), time_));
  pushLayers(std::move(after), tr("Remove layer intensity key"));
}

}  // namespace lacrima::editing
