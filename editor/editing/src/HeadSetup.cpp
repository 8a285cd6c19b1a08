#include <lacrima/editing/HeadSetup.h>

#include <lacrima/common/AtomicSave.h>
#include <lacrima/common/MediaFiles.h>
#include <lacrima/editing/HeadSetupCommands.h>
#include <lacrima/rigging/ClosestSurfacePoints.h>
#include <lacrima/rigging/DefaultHead.h>
#include <lacrima/rigging/FeaturePointProposal.h>
#include <lacrima/rigging/ImportProcess.h>

#include <QFileInfo>

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace lacrima::editing {
namespace {

// The file's role list a part's role goes to (nullptr: unlisted, follows the head).
std::vector<std::string>* roleList(rigging::FeaturePointFile& file, PartRole role) {
  switch (role) {
    case PartRole::Skin:
      return &file.skin;
    case PartRole::EyeLeft:
    case PartRole::CorneaLeft:
      return &file.eyeLeft.submeshes;
    case PartRole::EyeRight:
    case PartRole::CorneaRight:
      return &file.eyeRight.submeshes;
    case PartRole::TeethLower:
      return &file.jaw;
    case PartRole::Tongue:
      return &file.tongue;
    case PartRole::Attached:
      return &file.attached;
    case PartRole::Ignored:
      return &file.ignored;
    case PartRole::TeethUpper:
    case PartRole::Rigid:
      return nullptr;
  }
  return nullptr;
}

bool unlisted(PartRole role) { return role == PartRole::TeethUpper || role == PartRole::Rigid; }

}  // namespace

std::shared_ptr<const ProposalReference> ProposalReference::loadDefault() {
  auto reference = std::make_shared<ProposalReference>();
  reference->mesh = rigging::loadDefaultHead();
  reference->file = rigging::validateFeaturePoints(
      rigging::readFeaturePointFile(findMediaFile("default-head.fdp.json")), reference->mesh,
      nullptr);
  return reference;
}

HeadSetup::HeadSetup(QObject* parent) : QObject(parent) {}
HeadSetup::~HeadSetup() = default;

HeadMesh HeadSetup::importMesh(const QString& path, const rigging::ImportOptions& options) {
  return rigging::importHeadMeshIsolated(path.toStdString(), options);
}

void HeadSetup::setMesh(const QString& path, HeadMesh mesh) {
  if (mesh.triangleCount() == 0)
    throw std::invalid_argument(path.toStdString() + ": the mesh has no triangles");
  roles_ = guessPartRoles(mesh);
  mesh_ = std::make_shared<const HeadMesh>(std::move(mesh));
  meshPath_ = path;
  fdpPath_.clear();
  points_.clear();
  kept_ = {};
  undo_.clear();
  emit meshChanged();
  emit rolesChanged();
  emit pointsChanged();
  emit changed();
}

void HeadSetup::importFile(const QString& path) { setMesh(path, importMesh(path)); }

// --- roles -----------------------------------------------------------------------------

void HeadSetup::setRole(int submesh, PartRole role) {
  if (!hasMesh() || submesh < 0 || submesh >= static_cast<int>(roles_.size())) return;
  const PartRole before = roles_[static_cast<std::size_t>(submesh)];
  if (before == role) return;
  undo_.push(new SetPartRoleCommand(*this, submesh, before, role));
}

void HeadSetup::assignRole(int submesh, PartRole role) {
  roles_.at(static_cast<std::size_t>(submesh)) = role;
  emit rolesChanged();
  emit changed();
}

// --- points ----------------------------------------------------------------------------

const PlacedPoint* HeadSetup::point(const std::string& id) const {
  const auto it = points_.find(id);
  return it == points_.end() ? nullptr : &it->second;
}

std::optional<Eigen::Vector3d> HeadSetup::position(const std::string& id) const {
  const PlacedPoint* p = point(id);
  if (!p || !hasMesh()) return std::nullopt;
  return rigging::surfacePosition(p->spec.at, *mesh_);
}

int HeadSetup::submeshIndex(const std::string& name) const {
  const auto& parts = mesh_->submeshes;
  for (std::size_t i = 0; i < parts.size(); ++i)
    if (parts[i].name == name) return static_cast<int>(i);
  return -1;
}

void HeadSetup::placePoint(const std::string& id, const SurfaceSpot& spot) {
  if (!hasMesh()) throw std::invalid_argument("no head: import one first");
  const auto& parts = mesh_->submeshes;
  if (spot.submesh < 0 || spot.submesh >= static_cast<int>(parts.size()) || spot.triangle < 0 ||
      spot.triangle >=
          static_cast<int>(parts[static_cast<std::size_t>(spot.submesh)].triangles.size()))
    throw std::invalid_argument("feature point " + id + ": the spot is not on the head");
  SurfaceSpot on = spot;
  if (belongsOnSkin(id) && roles_[static_cast<std::size_t>(spot.submesh)] != PartRole::Skin) {
    const Eigen::Vector3i& tri = parts[static_cast<std::size_t>(spot.submesh)]
                                     .triangles[static_cast<std::size_t>(spot.triangle)];
    Eigen::Vector3d picked = Eigen::Vector3d::Zero();
    for (int k = 0; k < 3; ++k)
      picked += spot.barycentric[k] * mesh_->positions.col(tri[k]).cast<double>();
    if (const auto skin = snapToRole(picked, PartRole::Skin)) on = *skin;
  }
  const HeadSubmesh& part = parts[static_cast<std::size_t>(on.submesh)];
  rigging::SurfacePoint at;
  at.submesh = part.name;
  Eigen::Index corner = 0;
  // A click on a corner names the vertex, as hand-made files do; elsewhere the spot itself.
  if (on.barycentric.maxCoeff(&corner) >= 1.0 - 1e-3) {
    at.vertex = part.triangles[static_cast<std::size_t>(on.triangle)][corner] - part.firstVertex;
  } else {
    at.triangle = on.triangle;
    const Eigen::Vector3d b = on.barycentric.cwiseMax(0.0);
    at.barycentric = b / b.sum();
  }
  PlacedPoint placed;
  if (const PlacedPoint* old = point(id)) placed = *old;  // keeps a radius the file gave
  placed.spec.at = at;
  placed.spec.placedByHand = true;
  const PlacedPoint* before = point(id);
  undo_.push(new SetPointCommand(*this, id, before ? std::optional(*before) : std::nullopt, placed,
                                 tr("Place %1").arg(QString::fromStdString(id))));
}

std::optional<SurfaceSpot> HeadSetup::snapToRole(const Eigen::Vector3d& target,
                                                 PartRole role) const {
  if (!hasMesh()) return std::nullopt;
  std::vector<Eigen::Vector3i> triangles;
  std::vector<std::pair<int, int>> owner;  // (sub-mesh, local triangle) of each listed triangle
  for (std::size_t s = 0; s < mesh_->submeshes.size(); ++s) {
    if (roles_[s] != role) continue;
    const auto& tris = mesh_->submeshes[s].triangles;
    for (std::size_t t = 0; t < tris.size(); ++t) {
      triangles.push_back(tris[t]);
      owner.emplace_back(static_cast<int>(s), static_cast<int>(t));
    }
  }
  if (triangles.empty()) return std::nullopt;
  const Eigen::Matrix3Xd vertices = mesh_->positions.cast<double>();
  const rigging::SurfacePoints closest =
      rigging::closestSurfacePoints(vertices, triangles, Eigen::Matrix3Xd(target));
  const int k = closest.triangle(0);
  if (k < 0) return std::nullopt;
  return SurfaceSpot{owner[static_cast<std::size_t>(k)].first,
                     owner[static_cast<std::size_t>(k)].second, closest.barycentric.col(0)};
}

void HeadSetup::movePoint(const std::string& id, const Eigen::Vector3d& target) {
  const PlacedPoint* before = point(id);
  if (!before || !hasMesh()) return;
  const int part = submeshIndex(before->spec.at.submesh);
  if (part < 0) return;
  const auto spot = snapToRole(target, roles_[static_cast<std::size_t>(part)]);
  if (!spot) return;
  const PlacedPoint old = *before;
  const HeadSubmesh& sub = mesh_->submeshes[static_cast<std::size_t>(spot->submesh)];
  PlacedPoint moved = old;
  moved.spec.at = {};
  moved.spec.at.submesh = sub.name;
  moved.spec.at.triangle = spot->triangle;
  moved.spec.at.barycentric = spot->barycentric;
  moved.spec.placedByHand = true;
  undo_.push(
      new SetPointCommand(*this, id, old, moved, tr("Move %1").arg(QString::fromStdString(id))));
}

bool HeadSetup::belongsOnSkin(const std::string& id) {
  static const std::vector<std::string> elsewhere{"3.5", "3.6", "9.8", "9.9", "9.10", "9.11"};
  return id.rfind("6.", 0) != 0 &&
         std::find(elsewhere.begin(), elsewhere.end(), id) == elsewhere.end();
}

void HeadSetup::removePoint(const std::string& id) {
  const PlacedPoint* before = point(id);
  if (!before) return;
  undo_.push(new SetPointCommand(*this, id, *before, std::nullopt,
                                 tr("Remove %1").arg(QString::fromStdString(id))));
}

void HeadSetup::assignPoint(const std::string& id, const std::optional<PlacedPoint>& point) {
  if (point)
    points_[id] = *point;
  else
    points_.erase(id);
  emit pointsChanged();
  emit changed();
}

void HeadSetup::assignPoints(PlacedPoints points) {
  points_ = std::move(points);
  emit pointsChanged();
  emit changed();
}

// --- proposal --------------------------------------------------------------------------

rigging::FeaturePointFile HeadSetup::handFile() const {
  rigging::FeaturePointFile file = toFile();
  for (auto it = file.points.begin(); it != file.points.end();)
    it = it->second.placedByHand ? std::next(it) : file.points.erase(it);
  return file;
}

PlacedPoints HeadSetup::computeProposal(const rigging::FeaturePointFile& hand, const HeadMesh& mesh,
                                        const ProposalReference& reference, Warnings* warnings) {
  const rigging::FeaturePointFile checked =
      rigging::validateFeaturePoints(hand, mesh, warnings, rigging::FeaturePointSet::Partial);
  const rigging::FeaturePointFile complete =
      rigging::proposeFeaturePoints(checked, mesh, reference.file, reference.mesh, warnings);
  PlacedPoints out;
  for (const auto& [id, spec] : complete.points) {
    PlacedPoint p{spec};
    p.spec.placedByHand = hand.points.count(id) > 0;
    out.emplace(id, p);
  }
  return out;
}

void HeadSetup::applyProposal(const PlacedPoints& proposal) {
  PlacedPoints after;
  for (const auto& [id, p] : points_)
    if (p.byHand()) after.emplace(id, p);
  for (const auto& [id, p] : proposal)
    if (!p.byHand() && after.count(id) == 0) after.emplace(id, p);
  undo_.push(new SetPointsCommand(*this, points_, std::move(after), tr("Propose points")));
}

void HeadSetup::propose(const ProposalReference& reference, Warnings* warnings) {
  if (!hasMesh()) throw std::invalid_argument("no head: import one first");
  applyProposal(computeProposal(handFile(), *mesh_, reference, warnings));
}

// --- files -----------------------------------------------------------------------------

rigging::FeaturePointFile HeadSetup::toFile() const {
  rigging::FeaturePointFile file = kept_;
  file.path =
      (fdpPath_.isEmpty() ? meshPath_ + QStringLiteral(".fdp.json") : fdpPath_).toStdString();
  file.text.clear();
  if (hasMesh()) {
    file.meshNote = QFileInfo(meshPath_).fileName().toStdString();
    for (std::size_t s = 0; s < roles_.size(); ++s)
      if (auto* list = roleList(file, roles_[s])) list->push_back(mesh_->submeshes[s].name);
  }
  for (const auto& [id, p] : points_) file.points.emplace(id, p.spec);
  // Every point's position beside its index (FeaturePointFile.h), from the mesh as it is now:
  // a moved point's old position would otherwise send it back when the file is validated.
  if (hasMesh()) rigging::recordPositions(file, *mesh_);
  return file;
}

void HeadSetup::save(const QString& path) {
  rigging::FeaturePointFile file = toFile();
  file.path = path.toStdString();
  saveAtomically(file.path, rigging::featurePointFileJson(file));
  fdpPath_ = path;
  undo_.setClean();
}

void HeadSetup::openFeaturePoints(const QString& path, Warnings* warnings) {
  if (!hasMesh()) throw std::invalid_argument("no head: import one first");
  // Validation re-snaps points whose stored position the index no longer leads to (a
  // re-exported mesh) and refuses a file placed on another mesh.
  rigging::FeaturePointFile file = rigging::validateFeaturePoints(
      rigging::readFeaturePointFile(path.toStdString(), warnings), *mesh_, warnings,
      rigging::FeaturePointSet::Partial, QFileInfo(meshPath_).fileName().toStdString());

  std::vector<PartRole> roles = guessPartRoles(*mesh_);
  for (std::size_t s = 0; s < roles.size(); ++s) {
    const std::string& name = mesh_->submeshes[s].name;
    const auto in = [&](const std::vector<std::string>& list) {
      return std::find(list.begin(), list.end(), name) != list.end();
    };
    const bool cornea = roles[s] == PartRole::CorneaLeft || roles[s] == PartRole::CorneaRight;
    if (in(file.skin))
      roles[s] = PartRole::Skin;
    else if (in(file.eyeLeft.submeshes))
      roles[s] = cornea ? PartRole::CorneaLeft : PartRole::EyeLeft;
    else if (in(file.eyeRight.submeshes))
      roles[s] = cornea ? PartRole::CorneaRight : PartRole::EyeRight;
    else if (in(file.jaw))
      roles[s] = PartRole::TeethLower;
    else if (in(file.tongue))
      roles[s] = PartRole::Tongue;
    else if (in(file.attached))
      roles[s] = PartRole::Attached;
    else if (in(file.ignored))
      roles[s] = PartRole::Ignored;
    else if (!unlisted(roles[s]))
      roles[s] = PartRole::Rigid;  // the file says it only follows the head
  }
  PlacedPoints points;
  for (const auto& [id, spec] : file.points) points.emplace(id, PlacedPoint{spec});

  roles_ = std::move(roles);
  points_ = std::move(points);
  file.points.clear();
  file.skin.clear();
  file.jaw.clear();
  file.tongue.clear();
  file.attached.clear();
  file.ignored.clear();
  file.eyeLeft.submeshes.clear();
  file.eyeRight.submeshes.clear();
  kept_ = std::move(file);
  fdpPath_ = path;
  undo_.clear();
  emit rolesChanged();
  emit pointsChanged();
  emit changed();
}

}  // namespace lacrima::editing
