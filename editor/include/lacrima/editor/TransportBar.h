#pragma once
// Playback controls above the timeline: jump to start / previous key / play-pause / next key /
// end, loop, the time field, the playback rate (22 fps by default, as exported).
//
// The time field shows the playhead in seconds ("2.5 s") or frames ("55 f"; the s/f button
// switches) and takes a typed time: "2.5", "2.5s", "55f" (a bare number is in the unit shown).
// Enter jumps there, snapped to the frame grid as EditorModel::setCurrentTime snaps; a time it
// cannot take (negative, past an hour, "2.5f") is refused visibly, and the playhead stays.
// Up/Down step one frame. Ctrl+G (the window's "Go to time") focuses it.
#include <lacrima/editing/NumberInput.h>

#include <QWidget>

class QLabel;
class QToolButton;

namespace lacrima::editing {
class EditorModel;
class FrameStepClock;
}  // namespace lacrima::editing

namespace lacrima::editor {

class NumberField;

class TransportBar : public QWidget {
  Q_OBJECT
 public:
  TransportBar(editing::EditorModel& model, editing::FrameStepClock& clock,
               QWidget* parent = nullptr);

  QToolButton* playButton() const { return play_; }
  QToolButton* loopButton() const { return loop_; }
  NumberField* rateBox() const { return rate_; }
  NumberField* timeField() const { return timeField_; }
  QToolButton* timeUnitButton() const { return unit_; }  // checked: frames
  editing::TimeUnit timeUnit() const;
  // Focuses the time field with its text selected, ready to type over (Ctrl+G).
  void editTime();

  // Painted transport icons (no icon theme is needed).
  enum class Glyph { Start, PreviousKey, Play, Pause, NextKey, End, Loop, Key };
  static QIcon icon(Glyph glyph, const QColor& colour);

 private:
  void refreshTime();

  editing::EditorModel& model_;
  editing::FrameStepClock& clock_;
  QToolButton* play_;
  QToolButton* loop_;
  NumberField* timeField_;
  QToolButton* unit_;
  QLabel* time_;
  NumberField* rate_;
};

// Key navigation shared by the transport and the main window's shortcuts.
double previousKeyTime(const editing::EditorModel& model);  // current time when there is none
double nextKeyTime(const editing::EditorModel& model);

}  // namespace lacrima::editor
