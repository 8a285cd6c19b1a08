#pragma once
// The presets: expressions and crying presets from the presets file, applied at the current
// time with an intensity (0-150 %) and, by default, replacing the current pose. Mirror flips
// the selected keys (or the current pose) left <-> right.
#include <lacrima/editor/PresetLibrary.h>

#include <QWidget>

class QCheckBox;
class QLabel;
class QSlider;
class QTreeWidget;
class QPushButton;

namespace lacrima::editor {

class EditorModel;

class PresetPanel : public QWidget {
  Q_OBJECT
public:
  PresetPanel(EditorModel& model, PresetLibrary library, QWidget* parent = nullptr);

  void setLibrary(PresetLibrary library, const QString& source);
  const PresetLibrary& library() const { return library_; }

  double intensity() const;
  bool replacesPose() const;
  // Applies the preset with this id using the panel's intensity and replace setting.
  bool apply(const QString& id);
  QTreeWidget* list() const { return list_; }

signals:
  void loadRequested();

private:
  void rebuild();
  void showDetails();
  QString selectedId() const;

  EditorModel& model_;
  PresetLibrary library_;
  QString source_;
  QTreeWidget* list_;
  QLabel* details_;
  QSlider* intensity_;
  QLabel* intensityLabel_;
  QCheckBox* replace_;
  QPushButton* apply_;
};

}  // namespace lacrima::editor
