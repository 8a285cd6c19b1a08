#pragma once
// The live preview: the shared face viewport (lacrima::viewport::FaceViewport) showing the
// default head posed by the current slider values, with its tears.
//
// Driving the playback layer (lacrima::playback::FrameProducer on a HeadRig):
//   paused, no tears shown      -> producer.pose(values): the face only, nothing simulated;
//   playing                     -> producer.produce(values, dt, t / duration) once per playback
//                                  frame (dt = 1 / playback rate);
//   paused, a tear channel > 0
//   and "tear preview" on       -> produce() on an idle timer at the project's rate, so tears
//                                  keep running down the face while the animator works.
// A document change (new/open) resets the tears. The head is loaded once, after the window is
// up; when it is not fetched (or the viewport cannot render, e.g. on the offscreen platform)
// the panel says so and the editor works on without a preview.
#include <QWidget>

#include <memory>

class QLabel;
class QToolButton;
class QTimer;

namespace lacrima::editing {
class EditorModel;
class FrameStepClock;
}  // namespace lacrima::editing

namespace lacrima::editor {

class PreviewPanel : public QWidget {
  Q_OBJECT
 public:
  PreviewPanel(editing::EditorModel& model, editing::FrameStepClock& clock,
               QWidget* parent = nullptr);
  ~PreviewPanel() override;

  // Loads the default head now (also scheduled by the constructor). Returns whether a head is
  // shown.
  bool loadHead();
  bool hasHead() const;
  QString statusText() const;

  bool tearPreview() const { return tearPreview_; }
  void setTearPreview(bool on);

  // Advances the tears by `dt` seconds with the current values and shows the frame (the
  // playback tick and the idle tear timer call this; so does the benchmark).
  void step(double dt);
  // Re-poses the face for the current values without advancing the tears.
  void pose();
  int particleCount() const;
  double lastProduceMilliseconds() const { return lastProduceMs_; }
  // The viewport widget, or nullptr when there is no head.
  QWidget* viewportWidget() const;
  // Renders now and returns the picture (screenshots); null when there is no viewport.
  QImage grabFrame();

 signals:
  void statusChanged(const QString& text);

 private:
  void onValuesChanged();
  void updateIdleTimer();
  void setStatus(const QString& text);

  struct State;
  std::unique_ptr<State> state_;
  editing::EditorModel& model_;
  editing::FrameStepClock& clock_;
  QLabel* message_;
  QLabel* status_;
  QToolButton* tearToggle_;
  QTimer* idle_;
  bool tearPreview_ = true;
  double lastProduceMs_ = 0;
  QString statusText_;
};

}  // namespace lacrima::editor
