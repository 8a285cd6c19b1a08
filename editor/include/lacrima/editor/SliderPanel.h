#pragma once
// The 70 channels as sliders, grouped as the standard groups them (visemes and expressions,
// jaw and inner lips, eyes, eyebrows, cheeks, tongue, head, outer lips, nose, ears, then the
// tears). FAP 1 and 2 are pickers of their codes. A filter box narrows the list by name,
// number or group (ChannelFilter.h); each group folds and has a reset for all its channels.
//
// Speed: the rows are built once (about 300 widgets); a change of time or keys refreshes them
// in one pass that computes the key states once and touches only rows whose value or state
// changed, so scrubbing and playback do not re-layout anything.
#include <QWidget>

#include <array>
#include <vector>

class QComboBox;
class QLabel;
class QLineEdit;
class QScrollArea;
class QToolButton;

namespace lacrima::editing {
class EditorModel;
}  // namespace lacrima::editing

namespace lacrima::editor {

class ChannelRow;
class GroupSection;

class SliderPanel : public QWidget {
  Q_OBJECT
 public:
  explicit SliderPanel(editing::EditorModel& model, QWidget* parent = nullptr);

  void setFilterText(const QString& text);
  QLineEdit* filterBox() const { return filter_; }
  // Channels whose rows are visible under the current filter (tests, status).
  std::vector<int> visibleChannels() const;
  ChannelRow* row(int fap) const;  // nullptr for FAP 1 and 2 (pickers)
  QComboBox* visemePicker() const { return viseme_; }
  QComboBox* expressionPicker() const { return expression_; }
  QToolButton* groupResetButton(int group) const;
  QToolButton* symmetricButton() const { return symmetric_; }

  // Re-reads every value from the model (also done on every model change).
  void refresh();

 signals:
  // The expression picker asks for the expression's preset (applied by the main window).
  void expressionPresetRequested(int code);

 private:
  void buildGroups();
  void applyFilter();

  editing::EditorModel& model_;
  QLineEdit* filter_;
  QLabel* matchCount_;
  QScrollArea* scroll_;
  QToolButton* symmetric_;
  QComboBox* viseme_ = nullptr;
  QComboBox* expression_ = nullptr;
  std::vector<GroupSection*> groups_;
  std::array<ChannelRow*, 71> rows_{};  // by FAP number; [0], [1], [2] unused
  QWidget* visemeRow_ = nullptr;
  QWidget* expressionRow_ = nullptr;
  int highlighted_ = 0;
};

}  // namespace lacrima::editor
