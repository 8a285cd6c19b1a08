#pragma once
// The live preview: the shared face viewport (lacrima::viewport::FaceViewport) showing the
// project's head (ProjectDocument::head, or the default head) posed by the current slider
// values, with its tears.
//
// Driving the playback layer, with the face on the UI thread and the tears on a worker
// (lacrima::playback::PreviewWorker), so the window never waits for the simulation:
//   the face                    -> posed at once on the UI thread for the current values
//                                  (FrameProducer::pose: blending only, about a millisecond);
//   playing                     -> one tear request per playback frame (dt = 1 / playback rate,
//                                  progress = t / duration);
//   paused, a tear channel > 0
//   and "tear preview" on       -> one tear request per frame of the project's rate on an idle
//                                  timer, so tears keep running down the face while the
//                                  animator works. These live tears are an approximation of
//                                  the animation's (the player's tears at that time have run
//                                  since 0 s): the bar says so while they run.
// The worker drops requests rather than queueing them: while a step runs, a newer request
// replaces the waiting one, and each finished step is drawn over the face posed now. With 100,000
// particles the tears update every few seconds while sliders, the timeline and playback stay
// live. Tear channels set to 0 (no tear channel above 0 at the current time), Clear tears and a
// document change end the tears at once: the particles go from the view and the status line
// before the step still running ends (its result is thrown away).
//
// The head: once followDocumentHead() has been called (the window does, after it is up), the
// panel rigs the document's head on a worker thread (RigJob; progress in the message or the
// status) and rigs again whenever a document naming another head is opened or the head is
// changed (File > Choose head…). A head file that is missing, or a rig that fails, leaves the
// editor working without a preview and says what is wrong and what to do; the document keeps
// its head reference, so saving loses nothing. Rig warnings (a head without eyes: no tears)
// are counted in the status and listed in full by the warnings button beside it. When the
// viewport cannot render (the offscreen platform) the panel says so.
#include <QWidget>

#include <QStringList>

#include <memory>

class QLabel;
class QToolButton;
class QTimer;

namespace lacrima::viewport {
class ElidedLabel;
class WarningsButton;
}  // namespace lacrima::viewport

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
  // Vertices of the head shown (0 when none): which head the preview animates.
  int headVertexCount() const;
  // The rig's warnings for the head shown ("file: message").
  QStringList headWarnings() const;
  // The button beside the status that lists those warnings in full (hidden when none).
  viewport::WarningsButton* warningsButton() const { return warnings_; }
  QString statusText() const;
  // The text shown instead of the viewport (loading, a missing head file, no display); empty
  // while the viewport shows a head.
  QString messageText() const;

  bool tearPreview() const { return tearPreview_; }
  // Paused with tear preview on: the tears shown run live from where they were, which is not
  // what the animation (the player) shows at this time; the bar says so while true.
  bool showsLiveTears() const;
  void setTearPreview(bool on);
  // Threads the preview's tear simulation shares (--threads; FrameProducer::
  // setSimulationThreads), for the worker of each head shown from now on.
  void setSimulationThreads(int threads) { simulationThreads_ = threads; }

  // Poses the face for the current values now and asks the worker to advance the tears by `dt`
  // seconds (the playback tick and the idle tear timer call this; so does the benchmark). The
  // tears show when the worker's step ends: waitForTears() waits for it.
  void step(double dt);
  // Re-poses the face for the current values without advancing the tears.
  void pose();
  // Blocks until the worker has answered every request, then shows its last frame (tests,
  // benchmarks, screenshots).
  void waitForTears();
  // Tear particles shown (0 at once when the tears are set to 0 or cleared).
  int particleCount() const;
  // The last finished tear step on the worker (simulation, surface, trails, blend), ms.
  double lastProduceMilliseconds() const;
  // The viewport widget, or nullptr when there is no head.
  QWidget* viewportWidget() const;
  // Renders now and returns the picture (screenshots); null when there is no viewport.
  QImage grabFrame();

 signals:
  void statusChanged(const QString& text);
  // A head was installed (hasHead() may still be false without a display) or failed.
  void headReady();
  void headFailed(const QString& message);
  // A tear step finished on the worker: its tear cost (simulation + surface + trails, ms) and
  // sub-steps, once per step (the settings dialog shows them beside the quality choice).
  void tearsStepped(double milliseconds, long long substeps);

 private:
  void onValuesChanged();
  void onTearsReady();
  void draw();
  void showFigures();
  void updateIdleTimer();
  void retireWorker();
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
  viewport::ElidedLabel* status_;
  viewport::WarningsButton* warnings_;
  QToolButton* tearToggle_;
  QTimer* idle_;
  viewport::ElidedLabel* approximate_;
  bool tearPreview_ = true;
  int simulationThreads_ = 0;
  bool figuresShown_ = false;     // the status line shows the tear figures (not the head's)
  long long steppedRequest_ = 0;  // the worker frame tearsStepped() last reported
  QString statusText_;
};

}  // namespace lacrima::editor
