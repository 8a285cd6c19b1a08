#pragma once
// The ten tear parameters (common/TearParameters.h: names, ranges, descriptions) as spin
// boxes, with two presets: "2009 thesis" (the table's defaults, the settings of the 2009
// system) and "From the file" (what the open project set). Edits are gathered for a moment before
// edited() is emitted, since every change restarts the tears and replays up to the current time.
#include <lacrima/common/TearParameters.h>

#include <QWidget>

#include <vector>

class QDoubleSpinBox;
class QPushButton;
class QTimer;

namespace lacrima::player {

class TearParametersPanel : public QWidget {
  Q_OBJECT
 public:
  explicit TearParametersPanel(QWidget* parent = nullptr);

  // Shows `values` (overrides of the defaults) without emitting edited(); `fileValues` is what
  // the "File" preset restores.
  void display(const TearParameterValues& values, const TearParameterValues& fileValues);
  // The values shown, as overrides: only those that differ from the default.
  TearParameterValues values() const;

  QDoubleSpinBox* spinBox(std::string_view name) const;
  QPushButton* thesisPreset() const { return thesis_; }

 signals:
  void edited();

 private:
  void setShown(const TearParameterValues& values);

  std::vector<QDoubleSpinBox*> boxes_;  // in table order
  QPushButton *thesis_, *file_;
  TearParameterValues fileValues_;
  QTimer* settle_;
};

}  // namespace lacrima::player
