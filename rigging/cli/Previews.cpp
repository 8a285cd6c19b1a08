#include "Previews.h"

#include <lacrima/exporters/RigExport.h>

#include <algorithm>

namespace lacrima {
namespace {

bool has(const PreviewPoints& p, std::initializer_list<const char*> ids) {
  return std::all_of(ids.begin(), ids.end(), [&](const char* id) { return p.count(id) > 0; });
}

// One colour per FDP group, so neighbouring groups (lips 2.x / 8.x, lids 3.x / brows 4.x)
// are told apart at a glance.
QColor groupColour(const std::string& id) {
  const int group = std::atoi(id.c_str());
  switch (group) {
    case 2:
      return QColor(230, 30, 30);
    case 3:
      return QColor(30, 110, 240);
    case 4:
      return QColor(240, 150, 0);
    case 5:
      return QColor(0, 170, 90);
    case 6:
      return QColor(200, 0, 200);
    case 7:
      return QColor(0, 0, 0);
    case 8:
      return QColor(255, 230, 0);
    case 9:
      return QColor(0, 200, 220);
    case 10:
      return QColor(140, 70, 20);
    default:
      return QColor(255, 255, 255);
  }
}

}  // namespace

std::vector<exporters::PreviewPanel> previewPanels(const HeadMesh& mesh, const PreviewPoints& p) {
  const Eigen::Vector3d lo = mesh.boundsMin().cast<double>(), hi = mesh.boundsMax().cast<double>();
  const Eigen::Vector3d mid = 0.5 * (lo + hi);
  const double half = 0.55 * std::max({hi.x() - lo.x(), hi.y() - lo.y(), hi.z() - lo.z()});
  std::vector<exporters::PreviewPanel> panels{
      {exporters::PreviewPanel::View::Front, mid, half, "front"},
      {exporters::PreviewPanel::View::Side, mid, half, "side (from the face's left)"}};
  if (has(p, {"3.5", "3.6"})) {
    const double es0 = (p.at("3.5") - p.at("3.6")).norm();
    panels.push_back({exporters::PreviewPanel::View::Front, 0.5 * (p.at("3.5") + p.at("3.6")),
                      0.85 * es0, "eyes"});
  }
  if (has(p, {"8.3", "8.4"})) {
    const double mw0 = (p.at("8.3") - p.at("8.4")).norm();
    Eigen::Vector3d centre = 0.5 * (p.at("8.3") + p.at("8.4"));
    panels.push_back({exporters::PreviewPanel::View::Front, centre, 0.75 * mw0, "mouth"});
    panels.push_back({exporters::PreviewPanel::View::Side, centre, 0.75 * mw0, "mouth, side"});
  }
  return panels;
}

std::vector<exporters::PreviewMarker> previewMarkers(const PreviewPoints& points) {
  std::vector<exporters::PreviewMarker> out;
  for (const auto& [id, position] : points)
    out.push_back({QString::fromStdString(id), position, groupColour(id)});
  return out;
}

exporters::PreviewStyle previewStyle(const HeadMesh& mesh, const rigging::FeaturePointFile& fdp,
                                     int panelSize) {
  exporters::PreviewStyle style;
  style.panelSize = panelSize;
  auto in = [](const std::vector<std::string>& names, const std::string& n) {
    return std::find(names.begin(), names.end(), n) != names.end();
  };
  for (const HeadSubmesh& s : mesh.submeshes) {
    const bool transparent = s.material >= 0 &&
                             static_cast<std::size_t>(s.material) < mesh.materials.size() &&
                             mesh.materials[static_cast<std::size_t>(s.material)].transparent;
    if (in(fdp.attached, s.name))
      style.submeshColours.emplace_back(QColor(80, 55, 40));
    else if (exporters::isCorneaMaterial(mesh, s.material) || transparent)
      style.submeshColours.emplace_back(std::nullopt);
    else if (in(fdp.skin, s.name))
      style.submeshColours.emplace_back(QColor(228, 190, 165));
    else if (in(fdp.eyeLeft.submeshes, s.name) || in(fdp.eyeRight.submeshes, s.name))
      style.submeshColours.emplace_back(QColor(245, 245, 250));
    else if (in(fdp.tongue, s.name))
      style.submeshColours.emplace_back(QColor(200, 90, 95));
    else
      style.submeshColours.emplace_back(QColor(250, 248, 230));  // teeth and other rigid parts
  }
  return style;
}

}  // namespace lacrima
