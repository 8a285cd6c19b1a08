#pragma once
// Playback controls above the timeline: jump to start / previous key / play-pause / next key /
// end, the current time and frame, the playback rate (22 fps by default, as exported) and loop.
#include <QWidget>

class QDoubleSpinBox;
class QLabel;
class QSpinBox;
class QToolButton;

namespace lacrima::editing {
class EditorModel;
class FrameStepClock;
}  // namespace lacrima::editing

namespace lacrima::editor {

class TransportBar : public QWidget {
  Q_OBJECT
 public:
  TransportBar(editing::EditorModel& model, editing::FrameStepClock& clock,
               QWidget* parent = nullptr);

  QToolButton* playButton() const { return play_; }
  QSpinBox* rateBox() const { return rate_; }

  // Painted transport icons (no icon theme is needed).
  enum class Glyph { Start, PreviousKey, Play, Pause, NextKey, End, Loop, Key };
  static QIcon icon(Glyph glyph, const QColor& colour);

 private:
  void refreshTime();

  editing::EditorModel& model_;
  editing::FrameStepClock& clock_;
  QToolButton* play_;
  QLabel* time_;
  QSpinBox* rate_;
};

// Key navigation shared by the transport and the main window's shortcuts.
double previousKeyTime(const editing::EditorModel& model);  // current time when there is none
double nextKeyTime(const editing::EditorModel& model);

}  // namespace lacrima::editor
