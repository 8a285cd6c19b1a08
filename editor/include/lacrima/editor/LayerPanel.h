#pragma once
// The Layers panel: the presets added as layers (PoseLayer.h), each with its intensity at the
// playhead, a mute box and the number of intensity keys. Under the list, the selected layer's
// intensity can be keyed at the playhead (Enter or a step in the field, or "Key"; the field is
// a NumberField: a refused text changes nothing and says why), a key there removed,
// and the layer deleted. Every change goes through EditorModel and is one undo step. Above the
// list, the project's crying layer, when it has one (MoodLayerRow.h).
#include <QWidget>

class QPushButton;
class QTreeWidget;

namespace lacrima::editing {
class EditorModel;
}  // namespace lacrima::editing

namespace lacrima::editor {

class MoodLayerRow;
class NumberField;

class LayerPanel : public QWidget {
  Q_OBJECT
 public:
  explicit LayerPanel(editing::EditorModel& model, QWidget* parent = nullptr);

  QTreeWidget* list() const { return list_; }
  MoodLayerRow* moodLayer() const { return moodLayer_; }
  int selectedLayer() const;  // -1 when none
  // Keys the selected layer's intensity at the playhead from the field's text; false when the
  // text is refused (the field shows why: not a number in -100..100).
  bool keyTypedIntensity();

 private:
  void rebuild();
  void refreshValues();
  void updateButtons();

  editing::EditorModel& model_;
  MoodLayerRow* moodLayer_;
  QTreeWidget* list_;
  NumberField* intensity_;
  QPushButton* key_;
  QPushButton* unkey_;
  QPushButton* remove_;
  bool rebuilding_ = false;
};

}  // namespace lacrima::editor
