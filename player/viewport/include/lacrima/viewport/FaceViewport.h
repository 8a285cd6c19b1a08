#pragma once
// The face viewport: a Qt widget with an OGRE render window inside, showing a rigged head with
// its tears (FrameView.h). Shared by the player and the editor's live preview.
//
// Mouse: left drag orbits, right (or middle) drag pans, the wheel zooms; double-click or
// resetView() frames the face again. Rendering is on demand: a new frame revision, a camera move
// or a resize schedules one render; a static scene is not re-rendered.
//
// Needs an X display (OGRE on Debian is GLX only): run tests under xvfb-run. On any Qt platform
// other than xcb (the offscreen platform of headless tests, Wayland) the widget never starts
// OGRE: it shows the message "3-D preview needs an X display", every method is a safe no-op and
// grabFrame() returns a null image. If OGRE fails to start, the widget shows why the same way.
#include <lacrima/playback/FrameView.h>

#include <QImage>
#include <QWidget>

#include <memory>

namespace lacrima::viewport {

class FaceViewport : public QWidget {
  Q_OBJECT
 public:
  explicit FaceViewport(QWidget* parent = nullptr);
  ~FaceViewport() override;

  // The head to show; `neutral` must outlive the viewport (or the next setHead).
  void setHead(const HeadMesh& neutral);
  // Shows `view` on the next render when its revision differs from the last one shown.
  void showFrame(const playback::FrameView& view);
  void resetView();

  // Renders now and returns the picture (tests, screenshots).
  QImage grabFrame();
  double lastRenderMilliseconds() const;
  long long renderCount() const;  // renders so far: a static scene does not add any

  // Whether the widget draws with OGRE (false: it shows message() instead).
  bool usesOgre() const;
  QString message() const;

  QPaintEngine* paintEngine() const override { return nullptr; }

 signals:
  void rendered(double milliseconds);

 protected:
  void showEvent(QShowEvent* event) override;
  void paintEvent(QPaintEvent* event) override;
  void resizeEvent(QResizeEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void mouseDoubleClickEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;
  bool event(QEvent* event) override;                          // deferred render requests
  bool eventFilter(QObject* watched, QEvent* event) override;  // exposes of the native window

 private:
  void showMessage(const QString& text);
  void watchExposes();
  bool ensureScene();
  bool ensureWindow();
  void requestRender();
  bool renderNow(bool swap);

  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace lacrima::viewport
