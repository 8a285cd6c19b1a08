#pragma once
// The crying layer in the Layers panel (MoodLayer.h): on top of the pose layers, shown while the
// project has one. A box mutes it; the seed field re-seeds it (Enter, or "New seed" for the next
// seed); "Bake to keys" writes it into keys and removes it; "Delete" removes it. Its range and
// that it follows the mood curves (graph editor, Moods) are said beside it. Every change goes
// through EditorModel and is one undo step.
#include <QWidget>

class QCheckBox;
class QLabel;
class QLineEdit;
class QPushButton;

namespace lacrima::editing {
class EditorModel;
}  // namespace lacrima::editing

namespace lacrima::editor {

class MoodLayerRow : public QWidget {
  Q_OBJECT
 public:
  explicit MoodLayerRow(editing::EditorModel& model, QWidget* parent = nullptr);

  QCheckBox* enabled() const { return enabled_; }
  QLineEdit* seed() const { return seed_; }
  QPushButton* newSeed() const { return newSeed_; }
  QPushButton* bake() const { return bake_; }
  QPushButton* remove() const { return remove_; }

 private:
  void refresh();
  void applyTypedSeed();

  editing::EditorModel& model_;
  QCheckBox* enabled_;
  QLabel* range_;
  QLineEdit* seed_;
  QPushButton* newSeed_;
  QPushButton* bake_;
  QPushButton* remove_;
};

}  // namespace lacrima::editor
