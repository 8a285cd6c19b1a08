#include <lacrima/viewport/FaceViewport.h>

#include <lacrima/common/Milliseconds.h>
#include <lacrima/scene/FaceScene.h>
#include <lacrima/scene/OgreRuntime.h>

#include <OgreRenderWindow.h>
#include <OgreRoot.h>

#include <QApplication>
#include <QCoreApplication>
#include <QGuiApplication>
#include <QLabel>
#include <QMouseEvent>
#include <QVBoxLayout>
#include <QWheelEvent>
#include <QWindow>

#include <cmath>
#include <optional>
#include <string>

namespace lacrima::viewport {
namespace {

const QEvent::Type kRenderRequest = static_cast<QEvent::Type>(QEvent::registerEventType());

constexpr double kOrbitDegreesPerPixel = 0.35;
constexpr double kZoomPerNotch = 0.9;  // one wheel notch (120 units) closer

}  // namespace

struct FaceViewport::State {
  // OGRE is used only on X11 (xcb): OGRE on Debian renders through GLX. On other platforms
  // (offscreen in tests, Wayland without XWayland) the widget shows `message` instead and never
  // starts OGRE.
  bool ogre = false;
  QLabel* message = nullptr;

  std::shared_ptr<scene::OgreRuntime> runtime;
  std::unique_ptr<scene::FaceScene> scene;
  Ogre::RenderWindow* window = nullptr;
  const HeadMesh* head = nullptr;
  std::optional<long long> shownRevision;
  bool dirty = true, requestPosted = false;
  bool exposed = false;  // the window system reported lost pixels since the last render
  QWindow* watchedWindow = nullptr;
  long long renders = 0;
  double lastMilliseconds = 0;
  QPoint lastMouse;
  Qt::MouseButton dragButton = Qt::NoButton;
  QPoint pressedAt;
  bool claimed = false;    // the current drag belongs to a tool (claimDrag)
  bool movedAway = false;  // the current press has moved beyond the drag distance

  // What the scene is told once it exists (and again whenever it is re-created).
  std::vector<Marker> markers;
  Eigen::Matrix3d frame = Eigen::Matrix3d::Identity();
  // Picking: the positions of the last frame shown (copied: the frame's pointers expire), built
  // into a hierarchy on the first pick and refitted on the first pick after a new frame.
  std::vector<bool> pickable;
  Eigen::Matrix3Xf shownPositions;  // 3 x 0: the neutral positions are shown
  mutable std::unique_ptr<HeadPicker> picker;
  mutable bool pickerStale = false;

  void destroyWindow() {
    if (window && runtime) runtime->root().destroyRenderTarget(window);
    window = nullptr;
  }
  ~State() {
    destroyWindow();
    scene.reset();
    runtime.reset();
  }
};

FaceViewport::FaceViewport(QWidget* parent) : QWidget(parent), state_(std::make_unique<State>()) {
  // Qt paints nothing here itself: OGRE owns the pixels (or the message label covers them).
  setAttribute(Qt::WA_OpaquePaintEvent);
  setAttribute(Qt::WA_NoSystemBackground);
  setFocusPolicy(Qt::StrongFocus);
  setMinimumSize(64, 48);
  setMouseTracking(true);  // hovered()
  state_->ogre = QGuiApplication::platformName() == QLatin1String("xcb");
  if (state_->ogre) {
    setAttribute(Qt::WA_NativeWindow);
    setAttribute(Qt::WA_PaintOnScreen);
  } else {
    showMessage(tr("3-D preview needs an X display"));
  }
}

FaceViewport::~FaceViewport() = default;

void FaceViewport::showMessage(const QString& text) {
  State& s = *state_;
  s.destroyWindow();
  s.scene.reset();
  s.runtime.reset();
  s.ogre = false;
  setAttribute(Qt::WA_PaintOnScreen, false);
  if (!s.message) {
    s.message = new QLabel(this);
    s.message->setAlignment(Qt::AlignCenter);
    s.message->setWordWrap(true);
    s.message->setAutoFillBackground(true);
    QPalette palette = s.message->palette();
    palette.setColor(QPalette::Window, QColor(38, 39, 43));
    palette.setColor(QPalette::WindowText, QColor(170, 172, 178));
    s.message->setPalette(palette);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(s.message);
  }
  s.message->setText(text);
  s.message->show();
}

QString FaceViewport::message() const {
  return state_->message ? state_->message->text() : QString();
}

bool FaceViewport::usesOgre() const { return state_->ogre; }

bool FaceViewport::ensureScene() {
  State& s = *state_;
  if (!s.ogre) return false;
  if (s.scene) return true;
  try {
    s.runtime = scene::OgreRuntime::acquire();
    s.scene = std::make_unique<scene::FaceScene>(s.runtime);
    if (s.head) {
      s.scene->setHead(*s.head);
      s.scene->setViewFrame(s.frame);
    }
    s.scene->setMarkers(s.markers);
    return true;
  } catch (const std::exception& e) {
    showMessage(tr("3-D preview unavailable: %1").arg(QString::fromStdString(e.what())));
    return false;
  }
}

bool FaceViewport::ensureWindow() {
  State& s = *state_;
  if (s.window) return true;
  if (!isVisible() || width() <= 0 || height() <= 0 || !ensureScene()) return false;
  try {
    const qreal ratio = devicePixelRatioF();
    Ogre::NameValuePairList misc;
    misc["externalWindowHandle"] = std::to_string(static_cast<unsigned long long>(winId()));
    misc["vsync"] = "false";
    s.window = s.runtime->root().createRenderWindow(
        s.runtime->uniqueName("viewport"), static_cast<unsigned>(std::lround(width() * ratio)),
        static_cast<unsigned>(std::lround(height() * ratio)), false, &misc);
    s.window->setAutoUpdated(false);
    s.scene->attach(*s.window);
    s.dirty = true;
    return true;
  } catch (const std::exception& e) {
    showMessage(tr("3-D preview unavailable: %1").arg(QString::fromStdString(e.what())));
    return false;
  }
}

void FaceViewport::setHead(const HeadMesh& neutral) {
  State& s = *state_;
  s.head = &neutral;
  s.shownRevision.reset();
  s.frame = Eigen::Matrix3d::Identity();
  s.shownPositions.resize(3, 0);
  s.picker.reset();
  if (!s.ogre || !ensureScene()) return;
  s.scene->setHead(neutral);
  requestRender();
}

const HeadMesh* FaceViewport::head() const { return state_->head; }

void FaceViewport::showFrame(const playback::FrameView& view) {
  State& s = *state_;
  if (!s.ogre) return;
  if (view.neutral && view.neutral != s.head) setHead(*view.neutral);
  if (s.shownRevision && *s.shownRevision == view.revision) return;
  if (!ensureScene()) return;
  // Upload now: the frame's pointers are only valid until the producer's next frame.
  s.scene->show(view);
  s.shownRevision = view.revision;
  if (view.positions && s.head && view.positions->cols() == s.head->vertexCount()) {
    s.shownPositions = *view.positions;
    s.pickerStale = true;
  } else if (s.shownPositions.cols() > 0) {
    s.shownPositions.resize(3, 0);
    s.pickerStale = true;
  }
  requestRender();
}

void FaceViewport::resetView() {
  if (!state_->scene) return;
  state_->scene->resetView();
  requestRender();
}

void FaceViewport::setView(const scene::OrbitView& view) {
  if (!ensureScene()) return;
  state_->scene->setView(view);
  requestRender();
}

void FaceViewport::setViewFrame(const Eigen::Matrix3d& faceToHead) {
  State& s = *state_;
  s.frame = scene::faceFrameRotation(faceToHead);
  if (!s.scene) return;
  s.scene->setViewFrame(s.frame);
  requestRender();
}

Eigen::Matrix3d FaceViewport::viewFrame() const { return state_->frame; }

std::optional<QPointF> FaceViewport::project(const Eigen::Vector3d& point) const {
  const State& s = *state_;
  if (!s.scene || !s.scene->head()) return std::nullopt;
  const QPointF pixel = s.scene->project(point, size());
  if (!std::isfinite(pixel.x()) || !std::isfinite(pixel.y())) return std::nullopt;
  return pixel;
}

std::optional<Ray> FaceViewport::rayAt(QPointF pixel) const {
  const State& s = *state_;
  if (!s.scene) return std::nullopt;
  return s.scene->rayAt(pixel, size());
}

std::optional<SurfaceHit> FaceViewport::pick(QPointF pixel) const {
  const State& s = *state_;
  if (!s.head || s.head->triangleCount() == 0) return std::nullopt;
  const auto ray = rayAt(pixel);
  if (!ray) return std::nullopt;
  if (!s.picker) {
    s.picker = std::make_unique<HeadPicker>(*s.head, s.pickable);
    s.pickerStale = s.shownPositions.cols() > 0;
  }
  if (s.pickerStale) {
    s.picker->setPositions(s.shownPositions.cols() > 0 ? s.shownPositions : s.head->positions);
    s.pickerStale = false;
  }
  return s.picker->pick(*ray);
}

void FaceViewport::setPickableSubmeshes(std::vector<bool> pickable) {
  state_->pickable = std::move(pickable);
  state_->picker.reset();
}

void FaceViewport::setMarkers(std::vector<Marker> markers) {
  State& s = *state_;
  s.markers = std::move(markers);
  if (!s.scene) return;
  s.scene->setMarkers(s.markers);
  requestRender();
}

void FaceViewport::requestRender() {
  State& s = *state_;
  s.dirty = true;
  if (s.requestPosted || !s.ogre) return;
  s.requestPosted = true;
  QCoreApplication::postEvent(this, new QEvent(kRenderRequest));
}

void FaceViewport::watchExposes() {
  State& s = *state_;
  QWindow* window = windowHandle();
  if (!window || window == s.watchedWindow) return;
  if (s.watchedWindow) s.watchedWindow->removeEventFilter(this);
  window->installEventFilter(this);
  s.watchedWindow = window;
}

bool FaceViewport::eventFilter(QObject* watched, QEvent* event) {
  if (watched == state_->watchedWindow && event->type() == QEvent::Expose) state_->exposed = true;
  return QWidget::eventFilter(watched, event);
}

// OGRE's idea of the window's size (its viewport, the GL viewport, the camera's aspect) made
// equal to the widget's size in device pixels. Returns false while the widget has no area.
//
// Told through RenderWindow::resize, the external-window path, never windowMovedOrResized():
// that asks the X server through OGRE's own display connection, which can answer before Qt's
// own connection has delivered the resize (or for a moment when a layout gives the widget no
// area). A render with a size bigger than the window draws the picture magnified, cropped to
// its lower left: the head "blown up" to fill the view. Checking before every render also
// covers what sends no resize event at all (a change of device pixel ratio).
bool FaceViewport::syncWindowSize() {
  State& s = *state_;
  const qreal ratio = devicePixelRatioF();
  const auto w = static_cast<unsigned>(std::lround(width() * ratio)),
             h = static_cast<unsigned>(std::lround(height() * ratio));
  if (w == 0 || h == 0) return false;
  if (!s.window) return true;
  if (s.window->getWidth() == w && s.window->getHeight() == h) return true;
  s.window->resize(w, h);
  s.scene->setAspect(double(w) / double(h));
  return true;
}

bool FaceViewport::renderNow(bool swap) {
  State& s = *state_;
  if (!ensureWindow() || !syncWindowSize()) return false;
  const auto start = SteadyClock::now();
  s.window->update(swap);
  s.lastMilliseconds = millisecondsSince(start);
  s.dirty = false;
  s.exposed = false;
  ++s.renders;
  emit rendered(s.lastMilliseconds);
  return true;
}

QImage FaceViewport::grabFrame() {
  State& s = *state_;
  if (!s.ogre || !renderNow(false)) return {};
  const auto w = static_cast<Ogre::uint32>(s.window->getWidth()),
             h = static_cast<Ogre::uint32>(s.window->getHeight());
  QImage image(static_cast<int>(w), static_cast<int>(h), QImage::Format_RGBA8888);
  s.window->copyContentsToMemory(Ogre::Box(0, 0, w, h),
                                 Ogre::PixelBox(w, h, 1, Ogre::PF_BYTE_RGBA, image.bits()),
                                 Ogre::RenderTarget::FB_BACK);
  s.window->swapBuffers();
  return image;
}

double FaceViewport::lastRenderMilliseconds() const { return state_->lastMilliseconds; }

long long FaceViewport::renderCount() const { return state_->renders; }
bool FaceViewport::renderPending() const { return state_->dirty && state_->requestPosted; }

void FaceViewport::showEvent(QShowEvent* event) {
  QWidget::showEvent(event);
  if (!state_->ogre) return;
  watchExposes();
  requestRender();
}

void FaceViewport::paintEvent(QPaintEvent*) {
  // Paint events come from exposes and from update(). Only an expose loses the window's pixels
  // (the one case a static scene is drawn again); a plain update() of an unchanged scene is free.
  State& s = *state_;
  if (s.ogre && (s.dirty || s.exposed || !s.window)) renderNow(true);
}

void FaceViewport::resizeEvent(QResizeEvent* event) {
  QWidget::resizeEvent(event);
  if (!state_->window) return;
  syncWindowSize();
  requestRender();
}

void FaceViewport::claimDrag() { state_->claimed = true; }

void FaceViewport::mousePressEvent(QMouseEvent* event) {
  State& s = *state_;
  s.lastMouse = s.pressedAt = event->position().toPoint();
  s.dragButton = event->button();
  s.claimed = false;
  s.movedAway = false;
  emit pointerPressed(event->position(), event->button(), event->modifiers());
  event->accept();
}

void FaceViewport::mouseMoveEvent(QMouseEvent* event) {
  State& s = *state_;
  const QPoint now = event->position().toPoint();
  const QPoint delta = now - s.lastMouse;
  s.lastMouse = now;
  if (event->buttons() == Qt::NoButton) {
    emit hovered(event->position());
    return;
  }
  if ((now - s.pressedAt).manhattanLength() >= QApplication::startDragDistance())
    s.movedAway = true;
  if (s.claimed) {
    emit pointerDragged(event->position());
    event->accept();
    return;
  }
  if (!s.scene || delta.isNull()) return;
  scene::OrbitView view = s.scene->view();
  if (event->buttons() & Qt::LeftButton) {
    // Drag the head round: right turns it to its left, up tilts it back.
    view.orbit(-delta.x() * kOrbitDegreesPerPixel, delta.y() * kOrbitDegreesPerPixel);
  } else if (event->buttons() & (Qt::RightButton | Qt::MiddleButton)) {
    const double h = std::max(1, height());
    view.pan(-delta.x() / h, delta.y() / h);
  } else {
    return;
  }
  s.scene->setView(view);
  requestRender();
  event->accept();
}

void FaceViewport::mouseReleaseEvent(QMouseEvent* event) {
  State& s = *state_;
  const bool claimed = s.claimed, moved = s.movedAway;
  s.dragButton = Qt::NoButton;
  s.claimed = false;
  if (claimed)
    emit pointerReleased(event->position());
  else if (!moved)
    emit clicked(event->position(), event->button(), event->modifiers());
  event->accept();
}

void FaceViewport::mouseDoubleClickEvent(QMouseEvent* event) {
  resetView();
  event->accept();
}

void FaceViewport::wheelEvent(QWheelEvent* event) {
  State& s = *state_;
  if (!s.scene) return;
  const double notches = event->angleDelta().y() / 120.0;
  if (notches == 0) return;
  scene::OrbitView view = s.scene->view();
  view.zoom(std::pow(kZoomPerNotch, notches));
  s.scene->setView(view);
  requestRender();
  event->accept();
}

bool FaceViewport::event(QEvent* event) {
  State& s = *state_;
  if (event->type() == kRenderRequest) {
    s.requestPosted = false;
    if (s.dirty && s.ogre && isVisible()) renderNow(true);
    return true;
  }
  // Another screen may bring another device pixel ratio without a resize: the render re-sizes.
  if (event->type() == QEvent::ScreenChangeInternal && s.ogre) requestRender();
  if (event->type() == QEvent::WinIdChange && s.ogre) {
    // Re-parented into another top-level: the X window OGRE drew into is gone.
    s.destroyWindow();
    watchExposes();
    requestRender();
  }
  return QWidget::event(event);
}

}  // namespace lacrima::viewport
