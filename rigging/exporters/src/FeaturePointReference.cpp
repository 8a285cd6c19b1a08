#include <lacrima/exporters/FeaturePointReference.h>

#include <lacrima/common/FdpTable.h>
#include <lacrima/common/MediaFiles.h>
#include <lacrima/common/RayMesh.h>
#include <lacrima/exporters/RigExport.h>
#include <lacrima/rigging/DefaultHead.h>

#include <QPainter>

#include <algorithm>
#include <charconv>

namespace lacrima::exporters {
namespace {

std::pair<int, int> splitId(std::string_view id) {
  int group = 0, index = 0;
  const auto dot = id.find('.');
  if (dot == std::string_view::npos) return {0, 0};
  std::from_chars(id.data(), id.data() + dot, group);
  std::from_chars(id.data() + dot + 1, id.data() + id.size(), index);
  return {group, index};
}

std::optional<Eigen::Vector3d> pointOf(const ReferenceHead& head, const char* id) {
  const auto found = head.points.find(id);
  if (found == head.points.end()) return std::nullopt;
  return found->second;
}

PreviewPanel panelFor(const ReferenceHead& head, ReferenceView view, const Eigen::Vector3d& at) {
  const Eigen::Vector3d lo = head.mesh.boundsMin().cast<double>(),
                        hi = head.mesh.boundsMax().cast<double>();
  const double extent = (hi - lo).maxCoeff();
  using View = PreviewPanel::View;
  // A close-up on two points of the head (pupils, mouth corners), `widths` of their distance
  // from the middle to the edge, else around the point itself.
  auto closeUp = [&](const char* a, const char* b, double widths) {
    const auto p = pointOf(head, a), q = pointOf(head, b);
    if (p && q && (*p - *q).norm() > 0)
      return PreviewPanel{View::Front, 0.5 * (*p + *q), widths * (*p - *q).norm(), {}};
    return PreviewPanel{View::Front, at, 0.1 * extent, {}};
  };
  switch (view) {
    case ReferenceView::Eyes:
      return closeUp("3.5", "3.6", 0.85);  // both eyes and the brows above them
    case ReferenceView::Mouth:
      return closeUp("8.3", "8.4", 0.75);  // the lips with the nose's base and the chin's top
    case ReferenceView::Side:
      return {View::Side, 0.5 * (lo + hi), 0.55 * extent, {}};
    case ReferenceView::Face:
      break;
  }
  return {View::Front, 0.5 * (lo + hi), 0.55 * extent, {}};
}

// Pixel (y down) and the direction towards the viewer of a panel, as HeadPreview draws it.
QPointF pixelOf(const PreviewPanel& panel, int size, const Eigen::Vector3d& p) {
  const double scale = size / (2.0 * panel.halfSize), half = size / 2.0;
  const Eigen::Vector3d q = p - panel.centre;
  if (panel.view == PreviewPanel::View::Front) return {half + q.x() * scale, half - q.y() * scale};
  return {half - q.z() * scale, half - q.y() * scale};
}

// Whether the drawn surface hides `p` from an orthographic viewer of `panel`: a ray from in front
// of the whole head back towards p meets a shown triangle more than `tolerance` before it.
bool hiddenFrom(const ReferenceHead& head, const PreviewPanel& panel, const Eigen::Vector3d& p,
                double tolerance) {
  std::vector<Eigen::Vector3i> shown;
  for (std::size_t s = 0; s < head.mesh.submeshes.size(); ++s)
    if (s >= head.submeshColours.size() || head.submeshColours[s])
      shown.insert(shown.end(), head.mesh.submeshes[s].triangles.begin(),
                   head.mesh.submeshes[s].triangles.end());
  const Eigen::Vector3d towardsViewer =
      panel.view == PreviewPanel::View::Front ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d::UnitX();
  const double away = 2 * (head.mesh.boundsMax() - head.mesh.boundsMin()).cast<double>().norm();
  const RayMesh mesh(head.mesh.positions, std::move(shown));
  const auto hit = mesh.closestHit({p + away * towardsViewer, -towardsViewer});
  return hit && hit->distance < away - tolerance;
}

}  // namespace

ReferenceView referenceView(std::string_view id) {
  const auto [group, index] = splitId(id);
  if (group == 3 || group == 4) return ReferenceView::Eyes;
  if ((group == 2 && index >= 2 && index <= 9) || group == 8 || group == 6 ||
      (group == 9 && index >= 8 && index <= 11))
    return ReferenceView::Mouth;
  if ((group == 10 && index % 2 == 1) || id == "11.6" || id == "7.1") return ReferenceView::Side;
  return ReferenceView::Face;
}

ReferenceHead referenceHead(HeadMesh mesh, const rigging::FeaturePointFile& file) {
  ReferenceHead head;
  for (const auto& [id, spec] : file.points)
    head.points[id] = rigging::surfacePosition(spec.at, mesh);
  auto in = [](const std::vector<std::string>& names, const std::string& name) {
    return std::find(names.begin(), names.end(), name) != names.end();
  };
  for (const HeadSubmesh& s : mesh.submeshes) {
    const bool transparent = s.material >= 0 &&
                             static_cast<std::size_t>(s.material) < mesh.materials.size() &&
                             mesh.materials[static_cast<std::size_t>(s.material)].transparent;
    if (transparent || isCorneaMaterial(mesh, s.material))
      head.submeshColours.emplace_back(std::nullopt);  // cards and corneas would hide points
    else if (in(file.skin, s.name))
      head.submeshColours.emplace_back(QColor(228, 190, 165));
    else if (in(file.eyeLeft.submeshes, s.name) || in(file.eyeRight.submeshes, s.name))
      head.submeshColours.emplace_back(QColor(245, 245, 250));
    else if (in(file.tongue, s.name))
      head.submeshColours.emplace_back(QColor(200, 90, 95));
    else
      head.submeshColours.emplace_back(QColor(250, 248, 230));
  }
  head.mesh = std::move(mesh);
  return head;
}

ReferenceHead defaultReferenceHead() {
  HeadMesh mesh = rigging::loadDefaultHead();
  const rigging::FeaturePointFile file =
      rigging::readFeaturePointFile(findMediaFile("default-head.fdp.json"));
  rigging::validateFeaturePoints(file, mesh, nullptr);
  return referenceHead(std::move(mesh), file);
}

ReferencePicture renderFeaturePointReference(const ReferenceHead& head, std::string_view id,
                                             const ReferenceStyle& style) {
  ReferencePicture picture;
  const auto found = head.points.find(id);
  if (found == head.points.end() || style.size <= 0) return picture;
  const Eigen::Vector3d at = found->second;
  picture.view = referenceView(id);
  picture.panel = panelFor(head, picture.view, at);
  picture.panel.title = QString::fromUtf8(id.data(), int(id.size()));

  std::vector<PreviewMarker> others;
  for (const auto& [other, position] : head.points)
    if (other != id) others.push_back({QString(), position, style.others});
  PreviewStyle preview;
  preview.panelSize = style.size;
  preview.submeshColours = head.submeshColours;
  picture.image =
      renderHeadPreview(head.mesh, head.mesh.positions, {picture.panel}, others, preview);

  picture.pixel = pixelOf(picture.panel, style.size, at);
  picture.hidden = hiddenFrom(head, picture.panel, at, 0.01 * picture.panel.halfSize);
  QPainter painter(&picture.image);
  painter.setRenderHint(QPainter::Antialiasing);
  const double r = style.highlightRadius;
  // Cross hairs leading to the point from four sides, stopping short of it.
  painter.setPen(QPen(style.highlight, 2));
  for (const QPointF& d : {QPointF(1, 0), QPointF(-1, 0), QPointF(0, 1), QPointF(0, -1)})
    painter.drawLine(picture.pixel + d * (r + 6), picture.pixel + d * (r + 18));
  if (picture.hidden) {
    painter.setBrush(Qt::NoBrush);
    painter.setPen(QPen(style.highlight, 2, Qt::DashLine));
    painter.drawEllipse(picture.pixel, r, r);
  } else {
    painter.setBrush(Qt::NoBrush);
    painter.setPen(QPen(QColor(20, 20, 24), 1.5));
    painter.drawEllipse(picture.pixel, r + 2.5, r + 2.5);
    painter.setPen(QPen(Qt::white, 2));
    painter.drawEllipse(picture.pixel, r + 1, r + 1);
    painter.setPen(Qt::NoPen);
    painter.setBrush(style.highlight);
    painter.drawEllipse(picture.pixel, r, r);
  }
  return picture;
}

}  // namespace lacrima::exporters
