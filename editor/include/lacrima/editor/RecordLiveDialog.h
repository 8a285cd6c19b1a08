#pragma once
// Playback > Record live…: where to listen, how long to count in and which channels to key.
// The channels are FAP groups (all of them: every channel the stream sets) and, when channels
// are selected in the editor, optionally only those. LiveRecording does the recording.
#include <lacrima/common/FapChannels.h>
#include <lacrima/common/FapTable.h>

#include <QDialog>
#include <QString>

#include <optional>
#include <set>

class QCheckBox;
class QDialogButtonBox;
class QDoubleSpinBox;
class QLineEdit;

namespace lacrima::editor {

struct RecordLiveSettings {
  QString url = QStringLiteral("fap+tcp://127.0.0.1:5555");
  double countIn = 3.0;              // seconds, 0..kMaxCountIn
  std::set<FapGroup> skippedGroups;  // groups not keyed
  bool onlySelected = true;          // when some channels are selected
  static constexpr double kMaxCountIn = 10.0;
};

// The channels to key for `settings`: empty means every channel the stream sets (all groups,
// no selection applies); nullopt when nothing at all would be keyed.
std::optional<ChannelMask> recordedChannels(const RecordLiveSettings& settings,
                                            const ChannelMask& selected);

class RecordLiveDialog : public QDialog {
  Q_OBJECT
 public:
  RecordLiveDialog(const RecordLiveSettings& settings, const ChannelMask& selected,
                   QWidget* parent = nullptr);
  RecordLiveSettings settings() const;
  // The group's check box (tests).
  QCheckBox* groupBox(FapGroup group) const;
  QLineEdit* urlField() const { return url_; }
  QDoubleSpinBox* countInField() const { return countIn_; }
  QCheckBox* onlySelectedBox() const { return onlySelected_; }
  QDialogButtonBox* buttons() const { return buttons_; }

 private:
  void update();

  ChannelMask selected_;
  QLineEdit* url_ = nullptr;
  QDoubleSpinBox* countIn_ = nullptr;
  QCheckBox* onlySelected_ = nullptr;
  std::vector<std::pair<FapGroup, QCheckBox*>> groups_;
  QDialogButtonBox* buttons_ = nullptr;
};

}  // namespace lacrima::editor
