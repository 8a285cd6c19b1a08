#pragma once
// Software-rendered preview images of a head (QImage + QPainter, no GPU, no OGRE), for checking
// feature-point placement and poses by eye, on machines without a display.
//
// Each panel is an orthographic view: Front looks at the face along -z, as a person facing the
// head sees it (the face's left, +x, on the image's right); Side looks from the face's left (+x)
// along -x, so the face points to the image's left. Triangles are filled with
// a z-buffer and flat Lambert shading (two-sided, so the mouth cavity reads too), one colour per
// sub-mesh, or the sub-mesh's diffuse texture sampled at each triangle's uv centroid (enough to
// see the vermilion border of the lips or the iris, which is what placement is checked against);
// markers are dots with their labels, drawn filled where the surface does not hide
// them and as rings where it does.
#include <lacrima/common/HeadMesh.h>

#include <QColor>
#include <QImage>
#include <QString>

#include <Eigen/Core>

#include <optional>
#include <vector>

namespace lacrima::exporters {

struct PreviewPanel {
  enum class View { Front, Side };
  View view = View::Front;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  // model point at the panel's middle
  double halfSize = 1;                               // model units from the middle to an edge
  QString title;
};

struct PreviewMarker {
  QString label;
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  QColor colour = Qt::red;
};

struct PreviewStyle {
  int panelSize = 600;                                // pixels per square panel
  std::vector<std::optional<QColor>> submeshColours;  // per sub-mesh; nullopt hides it
  bool textured = true;  // shown sub-meshes with a readable diffuse texture use it
};

// Panels in a grid, three per row. `positions` are the (possibly deformed) vertices of `mesh` (same
// count). Needs a QGuiApplication for the labels' font (the offscreen platform is enough).
QImage renderHeadPreview(const HeadMesh& mesh, const Eigen::Matrix3Xf& positions,
                         const std::vector<PreviewPanel>& panels,
                         const std::vector<PreviewMarker>& markers, const PreviewStyle& style);

}  // namespace lacrima::exporters
