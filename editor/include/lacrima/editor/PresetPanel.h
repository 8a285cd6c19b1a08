#pragma once
// The presets: expressions and crying presets from the presets file, applied at the current
// time with an intensity (0-150 %: a slider and a field that takes whole percents exactly as
// typed) and, by default, replacing the current pose. Mirror flips the selected keys (or the
// current pose) left <-> right.
#include <lacrima/editing/PresetLibrary.h>

#include <QWidget>

class QCheckBox;
class QLabel;
class QSlider;
class QTreeWidget;
class QPushButton;

namespace lacrima::editing {
class EditorModel;
}  // namespace lacrima::editing

namespace lacrima::editor {

class NumberField;

class PresetPanel : public QWidget {
  Q_OBJECT
 public:
  PresetPanel(editing::EditorModel& model, editing::PresetLibrary library,
              QWidget* parent = nullptr);

  void setLibrary(editing::PresetLibrary library, const QString& source);
  const editing::PresetLibrary& library() const { return library_; }

  double intensity() const;
  bool replacesPose() const;
  // Whether presets become layers (EditorModel::applyPresetAsLayer) rather than keys.
  bool asLayer() const;
  void setAsLayer(bool layered);
  // Applies the preset with this id using the panel's intensity, replace and layer settings.
  bool apply(const QString& id);
  QTreeWidget* list() const { return list_; }
  NumberField* intensityField() const { return intensityField_; }

 signals:
  void loadRequested();

 private:
  void rebuild();
  void showDetails();
  QString selectedId() const;

  editing::EditorModel& model_;
  editing::PresetLibrary library_;
  QString source_;
  QTreeWidget* list_;
  QLabel* details_;
  QSlider* intensity_;
  NumberField* intensityField_;
  QCheckBox* replace_;
  QCheckBox* asLayer_;
  QPushButton* apply_;
};

}  // namespace lacrima::editor
