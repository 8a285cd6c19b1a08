#pragma once
// Playback controls above the timeline: jump to start / previous key / play-pause / next key /
// end, the current time and frame, the playback rate (22 fps by default, as exported) and loop.
#include <QWidget>

class QDoubleSpinBox;
class QLabel;
class QSpinBox;
class QToolButton;

namespace lacrima::editor {

class EditorModel;
class PlaybackClock;

class TransportBar : public QWidget {
  Q_OBJECT
public:
  TransportBar(EditorModel& model, PlaybackClock& clock, QWidget* parent = nullptr);

  QToolButton* playButton() const { return play_; }
  QSpinBox* rateBox() const { return rate_; }

  // Painted transport icons (no icon theme is needed).
  enum class Glyph { Start, PreviousKey, Play, Pause, NextKey, End, Loop, Key };
  static QIcon icon(Glyph glyph, const QColor& colour);

private:
  void refreshTime();

  EditorModel& model_;
  PlaybackClock& clock_;
  QToolButton* play_;
  QLabel* time_;
  QSpinBox* rate_;
};

// Key navigation shared by the transport and the main window's shortcuts.
double previousKeyTime(const EditorModel& model);  // current time when there is none
double nextKeyTime(const EditorModel& model);

}  // namespace lacrima::editor
