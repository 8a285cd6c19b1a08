#pragma once
// Animation ▸ Generate crying… (docs/editor.md, docs/mood.md): the moods, their intensities, the
// seed and the time range of a take of the crying generator, which the window writes as keys
// (planMoodGeneration) in one undo step. The range starts as the selected keys' span, else the
// whole take. The moods ease in from neutral over the first `ease` seconds of the range, so the
// take does not start on a full face. Or, when the project keys moods, the moods can come from
// its mood curves (MoodCurves.h) over the range instead, read at each generated frame. Or, under
// Output, the take can stay a procedural layer (MoodLayer.h, EditorModel::addMoodLayer) that
// follows the mood curves (constant moods are then keyed as curves over the range).
#include <lacrima/editing/MoodGeneration.h>

#include <QDialog>

#include <array>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;

namespace lacrima::editor {

class MoodGenerationDialog : public QDialog {
  Q_OBJECT
 public:
  // `start`, `end`: the range shown first; `fps`: the document's rate, the take's; `curves`: the
  // project's mood curves (they must outlive the dialog), offered when they have keys.
  MoodGenerationDialog(double start, double end, double fps, const MoodCurves* curves = nullptr,
                       QWidget* parent = nullptr);

  // What the fields say; throws std::invalid_argument naming the field that is wrong (an end
  // not after the start, a seed that is not a whole number).
  editing::MoodGenerationRequest request() const;

  QDoubleSpinBox* level(Mood mood) const { return levels_[static_cast<int>(mood)]; }
  QDoubleSpinBox* start() const { return start_; }
  QDoubleSpinBox* end() const { return end_; }
  QDoubleSpinBox* ease() const { return ease_; }
  QLineEdit* seed() const { return seed_; }
  QComboBox* presets() const { return presets_; }
  // "Constant moods" (0) or "The project's mood curves" (1).
  QComboBox* source() const { return source_; }
  // "Keys" (0) or "A procedural layer" (1).
  QComboBox* output() const { return output_; }
  bool asLayer() const;

 private:
  std::array<QDoubleSpinBox*, kMoodCount> levels_{};
  QDoubleSpinBox *start_, *end_, *ease_;
  QLineEdit* seed_;
  QComboBox* presets_;
  QComboBox* source_;
  QComboBox* output_;
  const MoodCurves* curves_;
  QLabel* problem_;
  double fps_;
};

}  // namespace lacrima::editor
