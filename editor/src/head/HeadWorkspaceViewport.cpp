// The Head workspace's viewport: the posed head, the markers, clicks that place the current
// point and drags that move one (HeadWorkspace.h).
#include <lacrima/editor/head/HeadWorkspace.h>

#include <lacrima/editing/EditorModel.h>
#include <lacrima/editing/HeadSetup.h>
#include <lacrima/editor/head/PointListModel.h>
#include <lacrima/playback/FrameProducer.h>
#include <lacrima/playback/HeadRig.h>
#include <lacrima/rigging/FaceFrame.h>
#include <lacrima/rigging/FeaturePointProposal.h>
#include <lacrima/viewport/FaceViewport.h>

#include <algorithm>
#include <utility>

namespace lacrima::editor::head {
namespace {

// A press and release closer than this (pixels, Manhattan) is a click, not a drag.
constexpr double kClickSlop = 4.0;

// A press this close to a marker's centre grabs it (pixels).
constexpr double kGrabRadius = 9.0;

QString text(const std::exception& e) { return QString::fromUtf8(e.what()); }

}  // namespace

void HeadWorkspace::pose() {
  if (!producer_ || !shownMesh_) return;
  const playback::FrameView& posed = producer_->pose(model_.currentValues());
  // Shown on the imported mesh, not the rig's copy of it (same vertices), so a new rig does
  // not re-frame the camera. The rig is in the face frame (FaceFrame.h); the workspace works in
  // the mesh's own coordinates: imported = R^T rig, R one of the 24 axis rotations.
  playback::FrameView view = posed;
  view.neutral = shownMesh_.get();
  const Eigen::Matrix3d& rotation = rig_->frame.rotation;
  if (!rotation.isIdentity() && posed.positions && posed.normals) {
    posedPositions_ = *posed.positions;
    posedNormals_ = *posed.normals;
    rigging::applyAxisRotation(rotation.transpose(), posedPositions_);
    rigging::applyAxisRotation(rotation.transpose(), posedNormals_);
    view.positions = &posedPositions_;
    view.normals = &posedNormals_;
  }
  shownPositions_ = view.positions;
  viewport_->showFrame(view);
  updateMarkers();
}

Eigen::Vector3d HeadWorkspace::shownPosition(const std::string& id) const {
  const editing::PlacedPoint* p = setup_->point(id);
  if (!p) return Eigen::Vector3d::Zero();
  const HeadMesh& mesh = setup_->mesh();
  const Eigen::Matrix3Xf& positions = shownPositions_ ? *shownPositions_ : mesh.positions;
  const std::vector<int> corners = rigging::surfaceVertices(p->spec.at, mesh);
  if (corners.size() == 1) return positions.col(corners[0]).cast<double>();
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (std::size_t k = 0; k < corners.size() && k < 3; ++k)
    sum += p->spec.at.barycentric[static_cast<Eigen::Index>(k)] *
           positions.col(corners[k]).cast<double>();
  return sum;
}

void HeadWorkspace::updateMarkers() {
  if (!setup_->hasMesh()) return;
  std::vector<viewport::Marker> markers;
  markers.reserve(setup_->points().size());
  for (const auto& [id, p] : setup_->points()) {
    viewport::Marker m;
    m.position = shownPosition(id);
    const bool current = id == current_;
    m.colour = current      ? PointColours::current()
               : p.byHand() ? PointColours::hand()
                            : PointColours::proposed();
    m.highlighted = current;
    m.onTop = current || id == dragged_;
    m.sizePixels = current ? 12 : 9;
    markers.push_back(m);
  }
  viewport_->setMarkers(std::move(markers));
}

void HeadWorkspace::updatePickable() {
  if (!setup_->hasMesh()) return;
  // Feature points sit on the skin, eyes, teeth and tongue: clicks go through lashes and tear
  // films (which lie over the eye corners) and through ignored parts.
  std::vector<bool> pickable;
  for (editing::PartRole role : setup_->roles())
    pickable.push_back(role != editing::PartRole::Ignored && role != editing::PartRole::Attached);
  viewport_->setPickableSubmeshes(std::move(pickable));
}

std::string HeadWorkspace::markerAt(QPointF pixel) const {
  std::string best;
  double bestDistance = kGrabRadius;
  for (const auto& [id, p] : setup_->points()) {
    const auto at = viewport_->project(shownPosition(id));
    if (!at) continue;
    const double d = QLineF(*at, pixel).length();
    // The current point wins a tie: it is the one being worked on.
    if (d < bestDistance || (d <= bestDistance && id == current_)) {
      bestDistance = d;
      best = id;
    }
  }
  if (best.empty()) return best;
  // A marker behind the head (the far ear) is not grabbed through it: the surface under the
  // mouse must be about where the marker is.
  if (const auto hit = viewport_->pick(pixel)) {
    const HeadMesh& mesh = setup_->mesh();
    const double size = (mesh.boundsMax() - mesh.boundsMin()).norm();
    if ((hit->position - shownPosition(best)).norm() > 0.05 * size && best != current_) return {};
  }
  return best;
}

bool HeadWorkspace::clickPlaces(QPointF pixel) {
  if (current_.empty() || !setup_->hasMesh()) return false;
  const auto hit = viewport_->pick(pixel);
  if (!hit) {
    setStatus(tr("Missed the head: click on it to place %1").arg(QString::fromStdString(current_)));
    return false;
  }
  editing::SurfaceSpot spot{hit->submesh, hit->submeshTriangle, hit->barycentric};
  try {
    setup_->placePoint(current_, spot);
  } catch (const std::exception& e) {
    fail(tr("Place"), text(e));
    return false;
  }
  const auto& anchors = rigging::proposalAnchors();
  if (std::find(anchors.begin(), anchors.end(), current_) != anchors.end())
    selectNextMissingAnchor();
  return true;
}

void HeadWorkspace::orientView() {
  // As soon as the eyes and the mouth (or chin) are placed, the face frame is known
  // (FaceFrame.h): orbit about the face's own up axis, so a Z-up head stands upright before it
  // is rigged. The view changes only when the nearest axis rotation does (not for a Y-up head).
  const auto axes = rigging::faceAxes(setup_->toFile(), setup_->mesh());
  if (!axes) return;
  const Eigen::Matrix3d faceToMesh = rigging::nearestAxisRotation(*axes).transpose();
  if (!viewport_->viewFrame().isApprox(faceToMesh)) viewport_->setViewFrame(faceToMesh);
}

void HeadWorkspace::connectViewport() {
  // A press on a marker takes the drag over from the camera; anywhere else the camera orbits.
  connect(viewport_, &viewport::FaceViewport::pointerPressed, this,
          [this](QPointF pixel, Qt::MouseButton button, Qt::KeyboardModifiers) {
            if (button != Qt::LeftButton || !setup_->hasMesh()) return;
            const std::string grabbed = markerAt(pixel);
            if (grabbed.empty()) return;
            dragged_ = grabbed;
            pressAt_ = pixel;
            setCurrentPoint(grabbed);
            viewport_->claimDrag();
          });
  connect(viewport_, &viewport::FaceViewport::pointerDragged, this, &HeadWorkspace::dragMarker);
  connect(viewport_, &viewport::FaceViewport::pointerReleased, this, &HeadWorkspace::dropMarker);
  connect(viewport_, &viewport::FaceViewport::clicked, this,
          [this](QPointF pixel, Qt::MouseButton button, Qt::KeyboardModifiers) {
            if (button == Qt::LeftButton) clickPlaces(pixel);
          });
}

void HeadWorkspace::dragMarker(QPointF pixel) {
  if (dragged_.empty()) return;
  // Follow the mouse on the surface; the document changes once, on release.
  const auto hit = viewport_->pick(pixel);
  if (!hit) return;
  std::vector<viewport::Marker> markers;
  viewport::Marker m;
  m.position = hit->position;
  m.colour = PointColours::current();
  m.highlighted = true;
  m.sizePixels = 12;
  markers.push_back(m);
  for (const auto& [id, p] : setup_->points()) {
    if (id == dragged_) continue;
    viewport::Marker other;
    other.position = shownPosition(id);
    other.colour = p.byHand() ? PointColours::hand() : PointColours::proposed();
    other.onTop = false;
    markers.push_back(other);
  }
  viewport_->setMarkers(std::move(markers));
}

void HeadWorkspace::dropMarker(QPointF pixel) {
  const std::string id = std::exchange(dragged_, std::string());
  // Pressed and released in place: the marker was only selected.
  if (!id.empty() && (pixel - pressAt_).manhattanLength() > kClickSlop) {
    if (const auto hit = viewport_->pick(pixel)) {
      // The neutral position under the hit (the head may be shown posed).
      const HeadMesh& mesh = setup_->mesh();
      const Eigen::Vector3i& tri = mesh.submeshes[static_cast<std::size_t>(hit->submesh)]
                                       .triangles[static_cast<std::size_t>(hit->submeshTriangle)];
      Eigen::Vector3d neutral = Eigen::Vector3d::Zero();
      for (int k = 0; k < 3; ++k)
        neutral += hit->barycentric[k] * mesh.positions.col(tri[k]).cast<double>();
      setup_->movePoint(id, neutral);
    }
  }
  updateMarkers();
}

}  // namespace lacrima::editor::head
