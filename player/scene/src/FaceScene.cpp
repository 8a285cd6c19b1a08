#include <lacrima/scene/FaceScene.h>

#include "HeadGeometry.h"
#include "HeadLook.h"
#include "MarkerLayer.h"
#include "StreamedGeometry.h"
#include "TearLayers.h"

#include <lacrima/scene/HeadOcclusion.h>
#include <lacrima/scene/HeadTangents.h>
#include <lacrima/scene/OgreRuntime.h>
#include <lacrima/scene/SkinDetail.h>
#include <lacrima/scene/SkinHorizons.h>
#include <lacrima/scene/UntexturedParts.h>

#include <OgreCamera.h>
#include <OgreEntity.h>
#include <OgreMaterialManager.h>
#include <OgreRenderQueue.h>
#include <OgreRenderTarget.h>
#include <OgreRoot.h>
#include <OgreSceneManager.h>
#include <OgreSceneNode.h>
#include <OgreViewport.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace lacrima::scene {
namespace {

// The backdrop: a neutral dark grey, lighter at the top, with a soft vignette, as a grid of
// coloured vertices in clip space (identity view and projection) on the far plane, so it costs
// no per-pixel work beyond the interpolation of a colour, and none where the head is: it is
// drawn after the opaque head (queue kBackdropQueue) and fails the depth test there.
std::unique_ptr<detail::StreamedGeometry> makeBackdrop(const std::string& name,
                                                       const std::string& group) {
  using Attribute = detail::StreamedGeometry::Attribute;
  static constexpr std::array kLayout{
      Attribute{Ogre::VET_FLOAT3, Ogre::VES_POSITION},
      Attribute{Ogre::VET_FLOAT3, Ogre::VES_TEXTURE_COORDINATES, 0}};
  auto backdrop = std::make_unique<detail::StreamedGeometry>(name, kLayout);
  constexpr int kColumns = 24, kRows = 14;
  auto smooth = [](double a, double b, double x) {
    const double t = std::clamp((x - a) / (b - a), 0.0, 1.0);
    return t * t * (3 - 2 * t);
  };
  float* out = backdrop->lockVertices((kColumns + 1) * (kRows + 1));
  for (int row = 0; row <= kRows; ++row)
    for (int column = 0; column <= kColumns; ++column) {
      const double u = double(column) / kColumns, v = double(row) / kRows;  // v = 0 at the top
      const double top[3] = {0.215, 0.22, 0.235}, bottom[3] = {0.085, 0.087, 0.095};
      const double g = smooth(0, 1, v);
      const double dx = (u - 0.5) * 1.6, dy = v - 0.42;
      const double vignette = 1 - 0.45 * smooth(0.25, 0.95, std::sqrt(dx * dx + dy * dy));
      *out++ = float(2 * u - 1);
      *out++ = float(1 - 2 * v);
      *out++ = 1.0f;  // the far plane
      for (int c = 0; c < 3; ++c) *out++ = float((top[c] + (bottom[c] - top[c]) * g) * vignette);
    }
  backdrop->unlockVertices();
  std::uint32_t* index = backdrop->lockIndices(6 * kColumns * kRows);
  for (int row = 0; row < kRows; ++row)
    for (int column = 0; column < kColumns; ++column) {
      const auto a = std::uint32_t(row * (kColumns + 1) + column), b = a + 1, c = a + kColumns + 1,
                 d = c + 1;
      for (std::uint32_t k : {a, c, b, b, c, d}) *index++ = k;
    }
  backdrop->unlockIndices();
  backdrop->setDrawn(6 * kColumns * kRows, Eigen::Vector3f(-1, -1, 0), Eigen::Vector3f(1, 1, 0));
  backdrop->setBoundingBox(Ogre::AxisAlignedBox::BOX_INFINITE);
  backdrop->setUseIdentityProjection(true);
  backdrop->setUseIdentityView(true);
  backdrop->setRenderQueueGroup(detail::kBackdropQueue);
  backdrop->setMaterial(
      Ogre::MaterialManager::getSingleton().getByName("Lacrima/Background", group));
  return backdrop;
}

}  // namespace

struct FaceScene::State {
  std::shared_ptr<OgreRuntime> runtime;
  Ogre::SceneManager* scene = nullptr;
  Ogre::Camera* camera = nullptr;
  Ogre::SceneNode* cameraNode = nullptr;
  Ogre::SceneNode* headNode = nullptr;
  Ogre::SceneNode* tearNode = nullptr;
  std::unique_ptr<detail::StreamedGeometry> backdrop;
  Ogre::SceneNode* backdropNode = nullptr;
  std::unique_ptr<detail::HeadGeometry> geometry;
  std::unique_ptr<detail::HeadLook> look;
  std::unique_ptr<detail::TearLayers> tears;
  std::unique_ptr<detail::MarkerLayer> markers;
  Ogre::SceneNode* markerNode = nullptr;
  Ogre::Viewport* viewport = nullptr;  // of attach(): its pixel size sizes the markers
  Eigen::Matrix3d frame = Eigen::Matrix3d::Identity();
  const HeadMesh* head = nullptr;
  OrbitView view = defaultView();
  double framingDistance = 0;  // of the head shown (skinDetailStrength)
  double aspect = 4.0 / 3.0;
  bool transparent = false;

  // The backdrop covers every pixel, so only depth and stencil (the trails' marks, TearLayers.h)
  // are cleared: clearing colour too would be a wasted pass over the frame. Transparent, the
  // backdrop is hidden and the colour cleared to alpha 0.
  void applyBackground() {
    backdropNode->setVisible(!transparent);
    if (!viewport) return;
    viewport->setBackgroundColour(transparent ? Ogre::ColourValue(0, 0, 0, 0)
                                              : Ogre::ColourValue(0.1f, 0.1f, 0.11f));
    viewport->setClearEveryFrame(true, transparent
                                           ? Ogre::FBT_COLOUR | Ogre::FBT_DEPTH | Ogre::FBT_STENCIL
                                           : Ogre::FBT_DEPTH | Ogre::FBT_STENCIL);
  }

  static OrbitView defaultView() {
    OrbitView v;
    v.distance = 5;
    return v;
  }

  ~State() {
    // Objects of the scene first (they reference its nodes and our materials), then the
    // scene manager; the runtime (shared_ptr) goes last.
    tears.reset();
    markers.reset();
    geometry.reset();
    look.reset();
    if (backdrop && backdropNode) backdropNode->detachObject(backdrop.get());
    backdrop.reset();
    if (scene) runtime->root().destroySceneManager(scene);
  }

  void applyCamera() {
    const Eigen::Vector3d eye = view.eye();
    const Eigen::Quaterniond q = view.orientation();
    cameraNode->setPosition(
        Ogre::Vector3(Ogre::Real(eye.x()), Ogre::Real(eye.y()), Ogre::Real(eye.z())));
    cameraNode->setOrientation(Ogre::Quaternion(Ogre::Real(q.w()), Ogre::Real(q.x()),
                                                Ogre::Real(q.y()), Ogre::Real(q.z())));
    camera->setFOVy(Ogre::Degree(Ogre::Real(view.fovYDegrees)));
    camera->setNearClipDistance(Ogre::Real(std::max(1e-4, 0.25 * view.minDistance)));
    camera->setFarClipDistance(Ogre::Real(4.0 * view.maxDistance + view.distance));
    camera->setAspectRatio(Ogre::Real(aspect));
    if (look) look->setDetailStrength(skinDetailStrength(view.distance, framingDistance));
    updateMarkers();
  }

  // Head frame to clip space under the current camera (what project() and the markers use).
  Eigen::Matrix4d viewProjection() const {
    const Ogre::Matrix4 m = camera->getProjectionMatrix() * camera->getViewMatrix();
    Eigen::Matrix4d out;
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) out(r, c) = m[r][c];
    return out;
  }

  void updateMarkers() {
    if (!markers || markers->empty() || !viewport) {
      if (markers) markers->update(Eigen::Matrix4d::Identity(), Eigen::Vector3d::Zero(), 0, 0);
      return;
    }
    markers->update(viewProjection(), view.eye(), viewport->getActualWidth(),
                    viewport->getActualHeight());
  }

  // A head without vertices or triangles shows nothing (only the backdrop and any tears).
  void buildHead(const HeadMesh& mesh) {
    look.reset();
    geometry.reset();
    head = &mesh;
    frame = Eigen::Matrix3d::Identity();
    if (mesh.vertexCount() > 0 && mesh.triangleCount() > 0) {
      detail::StaticShading shading{drawnUvs(mesh), headOcclusion(mesh), headTangents(mesh), {}};
      shading.horizons = skinHorizons(mesh, shading.tangents);
      auto built = std::make_unique<detail::HeadGeometry>(
          *scene, mesh, shading, runtime->uniqueName("head"), runtime->resourceGroup());
      look = std::make_unique<detail::HeadLook>(*runtime, mesh, *built);
      geometry = std::move(built);
      headNode->attachObject(&geometry->entity());
    }
    view = OrbitView::framing(mesh);
    framingDistance = view.distance;
    applyCamera();
  }
};

FaceScene::FaceScene(std::shared_ptr<OgreRuntime> runtime, const HeadMesh& head)
    : FaceScene(std::move(runtime)) {
  state_->buildHead(head);
}

FaceScene::FaceScene(std::shared_ptr<OgreRuntime> runtime) : state_(std::make_unique<State>()) {
  State& s = *state_;
  s.runtime = std::move(runtime);
  if (!s.runtime) throw std::invalid_argument("FaceScene: no OGRE runtime");
  s.scene = s.runtime->root().createSceneManager();
  s.camera = s.scene->createCamera(s.runtime->uniqueName("camera"));
  s.cameraNode = s.scene->getRootSceneNode()->createChildSceneNode();
  s.cameraNode->attachObject(s.camera);
  s.headNode = s.scene->getRootSceneNode()->createChildSceneNode();
  s.tearNode = s.scene->getRootSceneNode()->createChildSceneNode();

  s.backdrop = makeBackdrop(s.runtime->uniqueName("backdrop"), s.runtime->resourceGroup());
  s.backdropNode = s.scene->getRootSceneNode()->createChildSceneNode();
  s.backdropNode->attachObject(s.backdrop.get());

  s.tears = std::make_unique<detail::TearLayers>(
      *s.scene, *s.tearNode, s.runtime->uniqueName("tears"), s.runtime->resourceGroup());
  s.markerNode = s.scene->getRootSceneNode()->createChildSceneNode();
  s.markers = std::make_unique<detail::MarkerLayer>(*s.markerNode, s.runtime->uniqueName("markers"),
                                                    s.runtime->resourceGroup());
  s.applyCamera();
}

FaceScene::~FaceScene() = default;

void FaceScene::setHead(const HeadMesh& head) { state_->buildHead(head); }

const HeadMesh* FaceScene::head() const { return state_->head; }

void FaceScene::show(const playback::FrameView& view) {
  State& s = *state_;
  if (view.neutral && view.neutral != s.head) s.buildHead(*view.neutral);
  s.tears->showSurface(view.surface);
  s.tears->showDrops(view.drops);
  s.tears->showTrails(view.trails);
  s.tears->showParticles(view.particles, view.particleRadius);
  if (!s.geometry) return;
  const HeadMesh& head = *s.head;
  const Eigen::Matrix3Xf& positions = view.positions ? *view.positions : head.positions;
  const Eigen::Matrix3Xf& normals = view.normals ? *view.normals : head.normals;
  if (positions.cols() != head.positions.cols() || normals.cols() != head.positions.cols())
    throw std::invalid_argument("FaceScene::show: the frame has " +
                                std::to_string(positions.cols()) + " positions and " +
                                std::to_string(normals.cols()) + " normals, the head " +
                                std::to_string(head.positions.cols()) + " vertices");
  s.geometry->update(positions, normals);
  s.look->setOverlays(view.overlays, view.textureBlending);
}

Ogre::Viewport& FaceScene::attach(Ogre::RenderTarget& target) {
  Ogre::Viewport* viewport = target.addViewport(state_->camera);
  viewport->setOverlaysEnabled(false);
  viewport->setShadowsEnabled(false);
  state_->camera->setAutoAspectRatio(false);
  state_->viewport = viewport;
  state_->applyBackground();
  if (target.getHeight() > 0) setAspect(double(target.getWidth()) / double(target.getHeight()));
  return *viewport;
}

void FaceScene::setTransparentBackground(bool transparent) {
  state_->transparent = transparent;
  state_->applyBackground();
}

bool FaceScene::transparentBackground() const { return state_->transparent; }

void FaceScene::setAspect(double widthOverHeight) {
  if (!(widthOverHeight > 0) || !std::isfinite(widthOverHeight)) return;
  state_->aspect = widthOverHeight;
  state_->applyCamera();
}

const OrbitView& FaceScene::view() const { return state_->view; }

void FaceScene::setView(const OrbitView& view) {
  state_->view = view;
  state_->applyCamera();
}

void FaceScene::resetView() {
  setView(state_->head ? OrbitView::framing(*state_->head, state_->frame) : State::defaultView());
}

void FaceScene::setViewFrame(const Eigen::Matrix3d& faceToHead) {
  state_->frame = faceFrameRotation(faceToHead);
  resetView();
}

const Eigen::Matrix3d& FaceScene::viewFrame() const { return state_->frame; }

void FaceScene::setMarkers(std::vector<Marker> markers) {
  state_->markers->setMarkers(std::move(markers));
  state_->updateMarkers();
}

QPointF FaceScene::project(const Eigen::Vector3d& point, QSize size) const {
  const Ogre::Camera& camera = *state_->camera;
  const Ogre::Vector4 clip =
      camera.getProjectionMatrix() *
      (camera.getViewMatrix() *
       Ogre::Vector4(Ogre::Real(point.x()), Ogre::Real(point.y()), Ogre::Real(point.z()), 1));
  if (!(clip.w > 0))
    return {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
  const double x = clip.x / clip.w, y = clip.y / clip.w;
  return {(x + 1) * 0.5 * size.width(), (1 - y) * 0.5 * size.height()};
}

std::optional<Ray> FaceScene::rayAt(QPointF pixel, QSize size) const {
  if (size.isEmpty() || !std::isfinite(pixel.x()) || !std::isfinite(pixel.y())) return std::nullopt;
  // Undo project(): pixel to normalised device coordinates, then the points of the near and far
  // planes there back through (P V)^-1 (in double: the far plane is thousands of near-plane
  // distances away and float loses the direction's last digits).
  const double x = 2 * pixel.x() / size.width() - 1, y = 1 - 2 * pixel.y() / size.height();
  const Eigen::Matrix4d inverse = state_->viewProjection().inverse();
  const Eigen::Vector4d nearPoint = inverse * Eigen::Vector4d(x, y, -1, 1);
  const Eigen::Vector4d farPoint = inverse * Eigen::Vector4d(x, y, 1, 1);
  const Eigen::Vector3d origin = nearPoint.head<3>() / nearPoint.w();
  const Eigen::Vector3d direction = farPoint.head<3>() / farPoint.w() - origin;
  if (!origin.allFinite() || !(direction.norm() > 0) || !direction.allFinite()) return std::nullopt;
  return Ray{origin, direction.normalized()};
}

OgreRuntime& FaceScene::runtime() const { return *state_->runtime; }

}  // namespace lacrima::scene
