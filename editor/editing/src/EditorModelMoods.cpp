// EditorModel's mood curve edits (MoodCurves.h). Every edit is one MoodsCommand holding the
// four curves before and after.
#include <lacrima/common/mood/MoodScript.h>
#include <lacrima/editing/EditCommands.h>
#include <lacrima/editing/EditorModel.h>
#include <lacrima/editing/IntensityKeyEdits.h>

#include <algorithm>
#include <cmath>

namespace lacrima::editing {
namespace {

// What a project file accepts (ProjectDocument.h): times of a day, intensities in [0, 1]. Not
// a number becomes 0, so an edit never stores what the file would refuse.
IntensityCurve bounded(const IntensityCurve& curve) {
  std::vector<IntensityKey> keys = curve.keys();
  for (IntensityKey& key : keys) {
    key.time = std::isfinite(key.time) ? std::clamp(key.time, 0.0, MoodScript::kMaxTime) : 0.0;
    key.value = std::isfinite(key.value) ? std::clamp(key.value, 0.0, 1.0) : 0.0;
  }
  return IntensityCurve(std::move(keys));
}

}  // namespace

void EditorModel::applyMoods(const MoodCurves& moods) {
  document_.moods = moods;
  emit moodsChanged();
  if (!document_.moodLayer) return;
  refreshValues();  // the mood layer follows the curves
  emit valuesChanged();
}

void EditorModel::editMoods(MoodCurves after, const QString& text) {
  for (IntensityCurve& curve : after.curves) curve = bounded(curve);
  if (after == document_.moods) return;
  undo_.push(new MoodsCommand(*this, document_.moods, std::move(after), text));
}

void EditorModel::keyMood(Mood mood, double value) {
  if (!std::isfinite(value) || value < 0 || value > 1) {
    emit message(tr("A mood's intensity lies within 0..1"));
    return;
  }
  MoodCurves after = document_.moods;
  after[mood] = IntensityCurve(withKeyAt(after[mood].keys(), time_, value));
  editMoods(std::move(after),
            tr("Key %1").arg(QString::fromUtf8(moodName(mood).data(), int(moodName(mood).size()))));
}

void EditorModel::unkeyMood(Mood mood) {
  MoodCurves after = document_.moods;
  after[mood] = IntensityCurve(withoutKeyAt(after[mood].keys(), time_));
  editMoods(std::move(after), tr("Remove mood key"));
}

}  // namespace lacrima::editing
