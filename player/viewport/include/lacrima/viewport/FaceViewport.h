#pragma once
// The face viewport: a Qt widget with an OGRE render window inside, showing a rigged head with
// its tears (FrameView.h). Shared by the player and the editor's live preview.
//
// Picking (the Head workspace places feature points by clicking): project() maps a head point to
// widget pixels, rayAt() a pixel back to a ray, pick() finds where that ray meets the head as
// shown (HeadPicker.h). Markers (Marker.h) are discs drawn over the face, cheap to replace on
// every mouse move. setViewFrame() says which way an imported head's face looks, so the orbit
// turns about its up axis; until then a head is framed by its bounding box whatever its units
// and axes (OrbitView.h).
//
// Mouse: left drag orbits, right (or middle) drag pans, the wheel zooms; double-click or
// resetView() frames the face again. Tools get every press first (pointerPressed); a slot that
// calls claimDrag() there takes that drag over (pointerDragged, pointerReleased: dragging a
// feature point) and the camera stays put. A press and release without moving is clicked();
// moves without a button are hovered(). Rendering is on demand: a new frame revision, a camera move
// or a resize schedules one render; a static scene is not re-rendered.
//
// Needs an X display (OGRE on Debian is GLX only): run tests under xvfb-run. On any Qt platform
// other than xcb (the offscreen platform of headless tests, Wayland) the widget never starts
// OGRE: it shows the message "3-D preview needs an X display", every method is a safe no-op and
// grabFrame() returns a null image. If OGRE fails to start, the widget shows why the same way.
#include <lacrima/playback/FrameView.h>
#include <lacrima/scene/Marker.h>
#include <lacrima/scene/OrbitView.h>
#include <lacrima/viewport/HeadPicker.h>

#include <Eigen/Core>

#include <QImage>
#include <QWidget>

#include <memory>
#include <optional>
#include <vector>

namespace lacrima::viewport {

using Marker = scene::Marker;

class FaceViewport : public QWidget {
  Q_OBJECT
 public:
  explicit FaceViewport(QWidget* parent = nullptr);
  ~FaceViewport() override;

  // The head to show; `neutral` must outlive the viewport (or the next setHead).
  void setHead(const HeadMesh& neutral);
  // The head given to setHead (nullptr before).
  const HeadMesh* head() const;
  // Shows `view` on the next render when its revision differs from the last one shown.
  void showFrame(const playback::FrameView& view);
  void resetView();
  // Shows the head from `view` (a named camera, scene::presetView) until the user moves it;
  // resetView() goes back to the framing.
  void setView(const scene::OrbitView& view);
  // Which way the face looks (FaceScene::setViewFrame): columns are the face's left (its +x),
  // up and forward axes in head coordinates. Re-frames the view. setHead() resets it to identity.
  void setViewFrame(const Eigen::Matrix3d& faceToHead);
  Eigen::Matrix3d viewFrame() const;

  // Where a head-frame point shows in widget pixels (nullopt behind the camera or no scene).
  std::optional<QPointF> project(const Eigen::Vector3d& point) const;
  // The ray through a widget pixel, in head coordinates (origin on the near plane, unit
  // direction); nullopt without a scene.
  std::optional<Ray> rayAt(QPointF pixel) const;
  // The closest surface hit of that ray on the head as currently shown (the positions of the
  // last frame shown, else the neutral mesh), among the pickable sub-meshes. The first pick after
  // setHead builds the hierarchy (tens of ms on a 28k-vertex head); later ones take microseconds.
  std::optional<SurfaceHit> pick(QPointF pixel) const;
  // Per sub-mesh, whether pick() can hit it (empty: all; missing entries count as pickable).
  void setPickableSubmeshes(std::vector<bool> pickable);

  // Replaces the markers drawn over the face and renders once (Marker.h).
  void setMarkers(std::vector<Marker> markers);

  // Called from a slot of pointerPressed: the drag that press starts is the caller's (no
  // orbit or pan), reported by pointerDragged and pointerReleased.
  void claimDrag();

  // Renders now and returns the picture (tests, screenshots).
  QImage grabFrame();
  double lastRenderMilliseconds() const;
  long long renderCount() const;  // renders so far: a static scene does not add any
  bool renderPending() const;     // a render is asked for and has not run yet

  // Whether the widget draws with OGRE (false: it shows message() instead).
  bool usesOgre() const;
  QString message() const;

  QPaintEngine* paintEngine() const override { return nullptr; }

 signals:
  void rendered(double milliseconds);
  // Widget pixels. Every press, before the camera does anything with it.
  void pointerPressed(QPointF pixel, Qt::MouseButton button, Qt::KeyboardModifiers modifiers);
  void pointerDragged(QPointF pixel);   // a claimed drag moved
  void pointerReleased(QPointF pixel);  // a claimed drag ended
  // Pressed and released within the drag distance (QApplication::startDragDistance), unclaimed.
  void clicked(QPointF pixel, Qt::MouseButton button, Qt::KeyboardModifiers modifiers);
  void hovered(QPointF pixel);  // the mouse moved with no button down

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
  bool syncWindowSize();
  void requestRender();
  bool renderNow(bool swap);

  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace lacrima::viewport
