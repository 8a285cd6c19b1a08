#pragma once
// The player's main window: the face viewport in the middle, a transport bar under it
// (Play/Pause, Reset, the timeline, time), the effects and tear parameters at the side, the
// frame counter, frame rate and tear figures in the status bar.
//
// Timing. A wall clock (RealTimeClock) gives the animation time; a precise timer asks for it
// every few milliseconds and seeks the playback there: the tears advance one step per file
// frame, the face is interpolated at the exact time, and the viewport renders only when the
// frame's revision changed. So the picture is as smooth as the renderer is fast, whatever the
// file's rate. If the tears cannot keep up (a very heavy scene), the clock is held back to
// what was produced instead of piling up work: playback slows down, it never stalls.
//
// Files come in through one path, openFile(): the Open dialog, drag and drop, the command
// line and the "Open demo" action all use it. A file that cannot be read gives a dialog naming
// the file, line and what was expected; the animation that was playing stays. A project that
// names its own head is played on it (see setHeadSource).
#include <lacrima/player/RealTimeClock.h>

#include <lacrima/playback/HeadRig.h>
#include <lacrima/playback/LivePacer.h>
#include <lacrima/playback/LiveSource.h>
#include <lacrima/playback/Playback.h>
#include <lacrima/scene/CameraPreset.h>

#include <QMainWindow>

#include <deque>
#include <memory>
#include <optional>
#include <vector>

class QAction;
class QLabel;
class QMenu;
class QSlider;
class QTimer;

namespace lacrima::live {
class LiveSession;
struct ListenUrl;
}  // namespace lacrima::live

namespace lacrima::viewport {
class EffectsPanel;
class FaceViewport;
class WarningsButton;
}  // namespace lacrima::viewport

namespace lacrima::appsupport {
class ExportDialog;
}

namespace lacrima::player {

class LiveMappingDialog;
class LivePanel;
class MoodPanel;
class TearParametersPanel;

class PlayerWindow : public QMainWindow {
  Q_OBJECT
 public:
  explicit PlayerWindow(std::unique_ptr<playback::HeadRig> rig, QWidget* parent = nullptr);
  ~PlayerWindow() override;

  // Loads a FAP file or project and shows its first frame, paused. False (after an error
  // dialog) when the file cannot be used; the previous animation stays.
  bool openFile(const QString& path);
  void play();
  void pause();
  void togglePlay();
  void resetPlayback();  // neutral face, no tears, time 0
  void seek(double seconds);
  // What the rig was built from: a project's head files, or nullopt (the default head). Opening
  // a project that names another head (or none) rigs that head first, unless `fixed` (the
  // command line's --mesh/--fdp). A FAP file plays on the head shown.
  void setHeadSource(std::optional<HeadFiles> head, bool fixed);
  // The camera the face is shown from (--view), measured on the head shown and kept when a
  // project brings another head; Reset view (V) still goes back to the framing.
  void setCameraPreset(scene::CameraPreset preset);
  // The tear quality (--quality): applied now and to every file opened later, in place of the
  // file's own level (the Scene panel can still change it until the next file).
  void setTearQuality(TearQuality level);
  // Threads the tear simulation shares (--threads; Playback::setSimulationThreads), for this
  // animation's next tears and every file opened later.
  void setSimulationThreads(int threads);

  // Live input (--listen, Live > Listen...): the face follows the newest frame of every stream
  // listened to, the tears simulate at the display's pace, the timeline shows a live indicator.
  // Throws std::runtime_error (naming the URL) when the input cannot be opened; the stream
  // listened to before stays. Opening a file stops listening.
  void listen(const live::ListenUrl& url);
  void stopListening();
  bool isLive() const { return source_ == live_.get() && live_; }

  // Moods (--mood, the Mood panel, a stream's mood line; docs/mood.md): the crying generator
  // drives the face and the tears live, with no file. Starts it (on the live source, as a
  // stream would, without listening) when it is not running; otherwise the new levels are
  // targets the face eases toward. Opening a file stops it; a FAP frame from a stream takes
  // the face back until the next mood line.
  void playMoods(const MoodLevels& levels);
  // Another take of the generator (the Mood panel's seed and Randomise, --seed).
  void setMoodSeed(std::uint64_t seed);
  bool moodDriven() const { return isLive() && live_->moodDriven(); }
  MoodPanel& moodPanel() { return *moodPanel_; }
  live::LiveSession& liveSession() { return *session_; }
  playback::LiveSource* liveSource() { return live_.get(); }
  LivePanel& livePanel() { return *livePanel_; }
  // Live > Live Link mapping...: the gains, edited and applied to every Live Link input.
  LiveMappingDialog& mappingDialog();
  // What the transport shows: the file's Playback, or the live stream.
  playback::AnimationSource& source() { return *source_; }

  bool playing() const { return clock_.running(); }
  double renderedFramesPerSecond() const { return fps_; }
  playback::Playback& playback() { return *playback_; }
  const playback::HeadRig& rig() const { return *rig_; }
  viewport::FaceViewport& viewport() { return *viewport_; }
  QSlider& timeline() { return *timeline_; }
  viewport::EffectsPanel& effects() { return *effects_; }
  TearParametersPanel& parameters() { return *parameters_; }
  QAction* loopAction() const { return loop_; }  // checkable: play again from the start
  // File > Export...: the shared export dialog (appsupport/ExportDialog.h) on the file shown,
  // with the head shown. exportDialog() opens it (non-modal) and returns it, for tests; with no
  // file open (an animation set from memory) it opens nothing and returns nullptr.
  QAction* exportAction() const { return export_; }
  appsupport::ExportDialog* exportDialog();
  // View ▸ the named cameras (--view), one checked: the camera shown.
  QAction* cameraAction(scene::CameraPreset preset) const;
  // The rig's warnings, counted in the status bar and listed in full when clicked.
  viewport::WarningsButton& rigWarnings() { return *rigWarnings_; }

  // Error dialogs are window-modal and do not block; tests and scripts may turn them off
  // (the error still goes to stderr and the status bar).
  void setErrorDialogsEnabled(bool on) { errorDialogs_ = on; }

 signals:
  void fileOpened(const QString& path);
  void openFailed(const QString& message);

 protected:
  void dragEnterEvent(QDragEnterEvent* event) override;
  void dropEvent(QDropEvent* event) override;

 private:
  void buildActions();
  void buildLayout();
  void chooseFile();
  void openDemo();
  void tick();
  void display(const playback::FrameView& view);
  void applyScene();
  void applyTearQuality();
  void recordTearCost(long long framesBefore);
  void updateTransport();
  void updatePlayIcon();
  void countRender();
  void timelineMoved(int milliseconds);
  void reportError(const std::exception& error, const QString& path);
  void showRigWarnings();
  void chooseStream();
  void editMapping();
  void liveFrameArrived();
  void startLiveSource();
  void stopLiveSource();

  std::unique_ptr<playback::HeadRig> rig_;
  scene::CameraPreset cameraPreset_ = scene::CameraPreset::Framing;
  std::unique_ptr<playback::Playback> playback_;
  std::unique_ptr<playback::LiveSource> live_;
  playback::AnimationSource* source_;  // playback_ or live_
  live::LiveSession* session_;
  LivePanel* livePanel_;
  MoodPanel* moodPanel_;
  LiveMappingDialog* mappingDialog_ = nullptr;
  std::optional<HeadFiles> head_;  // setHeadSource()
  bool headFixed_ = false;
  std::optional<TearQuality> tearQuality_;  // setTearQuality()
  int simulationThreads_ = 0;               // setSimulationThreads()
  RealTimeClock clock_;
  QTimer* ticker_;
  viewport::FaceViewport* viewport_;
  QSlider* timeline_;
  QLabel *timeLabel_, *frameLabel_, *fpsLabel_, *tearsLabel_;
  viewport::EffectsPanel* effects_;
  TearParametersPanel* parameters_;
  QMenu* viewMenu_;
  std::vector<QAction*> cameraActions_;  // in CameraPreset order
  viewport::WarningsButton* rigWarnings_;
  QAction *listen_, *stopListening_;
  QAction* export_ = nullptr;
  QAction *open_, *openDemo_, *play_, *reset_, *loop_, *resetView_, *quit_, *stepBack_,
      *stepForward_;
  TearParameterValues fileParameters_;
  std::deque<qint64> renderTimes_;  // ms stamps of the last second's renders
  QElapsedTimer sinceStart_;
  double fps_ = 0;
  qint64 liveStatusShown_ = -1000;  // sinceStart_ ms of the last live status shown
  long long liveTearsCosted_ = 0;   // the live tear step last counted in the cost figure
  playback::LivePacer pacer_;       // when a live tick renders (LivePacer.h)
  double liveTickAt_ = -1;          // the live tick whose render is pending, for the pacer
  bool playAfterScrub_ = false, errorDialogs_ = true;
};

}  // namespace lacrima::player
