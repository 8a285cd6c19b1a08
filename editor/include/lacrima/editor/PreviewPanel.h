#pragma once
// The live preview: the shared face viewport (lacrima::viewport::FaceViewport) showing the
// project's head (ProjectDocument::head, or the default head) posed by the current slider
// values, with its tears.
//
// Driving the playback layer (lacrima::playback::FrameProducer on a HeadRig):
//   paused, no tears shown      -> producer.pose(values): the face only, nothing simulated;
//   playing                     -> producer.produce(values, dt, t / duration) once per playback
//                                  frame (dt = 1 / playback rate);
//   paused, a tear channel > 0
//   and "tear preview" on       -> produce() on an idle timer at the project's rate, so tears
//                                  keep running down the face while the animator works.
// A document change (new/open) resets the tears.
//
// The head: once followDocumentHead() has been called (the window does, after it is up), the
// panel rigs the document's head on a worker thread (RigJob; progress in the message or the
// status) and rigs again whenever a document naming another head is opened or the head is
// changed (File > Choose head…). A head file that is missing, or a rig that fails, leaves the
// editor working without a preview and says what is wrong and what to do; the document keeps
// its head reference, so saving loses nothing. Rig warnings (a head without eyes: no tears)
// go to the status. When the viewport cannot render (the offscreen platform) the panel says so.
#include <QWidget>

#include <QStringList>

#include <memory>

class QLabel;
class QToolButton;
class QTimer;

namespace lacrima::playback {
struct HeadRig;
}

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

  // Starts showing the document's head (in the background) and follows it from now on.
  void followDocumentHead();
  // followDocumentHead(), then waits (turning the event loop) until the head is rigged or has
  // failed: for tests and batch screenshots. Returns whether a head is shown.
  bool loadHead();
  bool hasHead() const;
  bool headLoading() const;
  // Vertices of the head shown (0 when none): which head the preview animates.
  int headVertexCount() const;
  // The rig's warnings for the head shown ("file: message").
  QStringList headWarnings() const;
  QString statusText() const;
  // The text shown instead of the viewport (loading, a missing head file, no display); empty
  // while the viewport shows a head.
  QString messageText() const;

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
  // A head was installed (hasHead() may still be false without a display) or failed.
  void headReady();
  void headFailed(const QString& message);

 private:
  void onValuesChanged();
  void updateIdleTimer();
  void setStatus(const QString& text);
  void syncHead(bool retryFailed);
  void installRig(std::shared_ptr<playback::HeadRig> rig);
  void showRigFailure(const QString& error);
  void showMessage(const QString& text);

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
