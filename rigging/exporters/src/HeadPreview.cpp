#include <lacrima/exporters/HeadPreview.h>

#include <Eigen/Geometry>
#include <QFont>
#include <QPainter>

#include <algorithm>
#include <cmath>
#include <limits>

namespace lacrima::exporters {
namespace {

// Screen coordinates (pixels, y down) and depth (larger = nearer the viewer) of a model point.
struct Projector {
  const PreviewPanel& panel;
  double scale;  // pixels per model unit
  double half;   // panel size / 2

  Eigen::Vector3d operator()(const Eigen::Vector3d& p) const {
    const Eigen::Vector3d q = p - panel.centre;
    if (panel.view == PreviewPanel::View::Front)
      return {half + q.x() * scale, half - q.y() * scale, q.z()};
    return {half - q.z() * scale, half - q.y() * scale, q.x()};
  }
  Eigen::Vector3d viewDirection() const {  // towards the viewer
    return panel.view == PreviewPanel::View::Front ? Eigen::Vector3d::UnitZ()
                                                   : Eigen::Vector3d::UnitX();
  }
};

// Diffuse textures by material, loaded once per image (null images for none or unreadable).
std::vector<QImage> loadTextures(const HeadMesh& mesh, bool textured) {
  std::vector<QImage> out(mesh.materials.size());
  if (!textured || mesh.uvs.cols() != mesh.positions.cols()) return out;
  for (std::size_t m = 0; m < out.size(); ++m)
    if (!mesh.materials[m].diffuseTexture.empty())
      out[m] = QImage(QString::fromStdString(mesh.materials[m].diffuseTexture))
                   .convertToFormat(QImage::Format_RGB32);
  return out;
}

void renderPanel(QImage& image, int x0, int y0, const HeadMesh& mesh,
                 const Eigen::Matrix3Xf& positions, const PreviewPanel& panel,
                 const std::vector<PreviewMarker>& markers, const PreviewStyle& style,
                 const std::vector<QImage>& textures) {
  const int size = style.panelSize;
  const Projector project{panel, size / (2.0 * panel.halfSize), size / 2.0};
  std::vector<double> depth(static_cast<std::size_t>(size) * static_cast<std::size_t>(size),
                            -std::numeric_limits<double>::infinity());
  // Light from the viewer's upper left, so relief shows on both views.
  const Eigen::Vector3d toViewer = project.viewDirection();
  const Eigen::Vector3d light =
      (toViewer + 0.5 * Eigen::Vector3d::UnitY() + 0.4 * toViewer.cross(Eigen::Vector3d::UnitY()))
          .normalized();

  for (std::size_t s = 0; s < mesh.submeshes.size(); ++s) {
    const std::optional<QColor> colour = s < style.submeshColours.size()
                                             ? style.submeshColours[s]
                                             : std::optional<QColor>(QColor(200, 200, 200));
    if (!colour) continue;
    const int material = mesh.submeshes[s].material;
    const QImage* texture =
        material >= 0 && static_cast<std::size_t>(material) < textures.size() &&
                !textures[static_cast<std::size_t>(material)].isNull() &&
                !mesh.materials[static_cast<std::size_t>(material)].transparent  // alpha cards
            ? &textures[static_cast<std::size_t>(material)]
            : nullptr;
    for (const Eigen::Vector3i& t : mesh.submeshes[s].triangles) {
      const Eigen::Vector3d a = positions.col(t[0]).cast<double>(),
                            b = positions.col(t[1]).cast<double>(),
                            c = positions.col(t[2]).cast<double>();
      const Eigen::Vector3d n = (b - a).cross(c - a);
      if (!(n.norm() > 0)) continue;
      const double shade = 0.25 + 0.75 * std::abs(n.normalized().dot(light));
      QColor base = *colour;
      if (texture) {  // uvs are OGRE-style, v down: row = v * height
        const Eigen::Vector2f uv =
            (mesh.uvs.col(t[0]) + mesh.uvs.col(t[1]) + mesh.uvs.col(t[2])) / 3.0f;
        const int tx = std::clamp(static_cast<int>(uv.x() * static_cast<float>(texture->width())),
                                  0, texture->width() - 1);
        const int ty = std::clamp(static_cast<int>(uv.y() * static_cast<float>(texture->height())),
                                  0, texture->height() - 1);
        base = QColor(texture->pixel(tx, ty));
      }
      const QRgb rgb =
          qRgb(static_cast<int>(base.red() * shade), static_cast<int>(base.green() * shade),
               static_cast<int>(base.blue() * shade));
      const Eigen::Vector3d p0 = project(a), p1 = project(b), p2 = project(c);
      const double area =
          (p1.x() - p0.x()) * (p2.y() - p0.y()) - (p2.x() - p0.x()) * (p1.y() - p0.y());
      if (std::abs(area) < 1e-12) continue;
      const int xmin =
          std::max(0, static_cast<int>(std::floor(std::min({p0.x(), p1.x(), p2.x()}))));
      const int xmax =
          std::min(size - 1, static_cast<int>(std::ceil(std::max({p0.x(), p1.x(), p2.x()}))));
      const int ymin =
          std::max(0, static_cast<int>(std::floor(std::min({p0.y(), p1.y(), p2.y()}))));
      const int ymax =
          std::min(size - 1, static_cast<int>(std::ceil(std::max({p0.y(), p1.y(), p2.y()}))));
      for (int y = ymin; y <= ymax; ++y) {
        QRgb* line = reinterpret_cast<QRgb*>(image.scanLine(y0 + y));
        for (int x = xmin; x <= xmax; ++x) {
          const double px = x + 0.5, py = y + 0.5;
          const double w0 = ((p1.x() - px) * (p2.y() - py) - (p2.x() - px) * (p1.y() - py)) / area;
          const double w1 = ((p2.x() - px) * (p0.y() - py) - (p0.x() - px) * (p2.y() - py)) / area;
          const double w2 = 1.0 - w0 - w1;
          if (w0 < 0 || w1 < 0 || w2 < 0) continue;
          const double z = w0 * p0.z() + w1 * p1.z() + w2 * p2.z();
          double& slot = depth[static_cast<std::size_t>(y) * static_cast<std::size_t>(size) +
                               static_cast<std::size_t>(x)];
          if (z <= slot) continue;
          slot = z;
          line[x0 + x] = rgb;
        }
      }
    }
  }

  QPainter painter(&image);
  painter.setRenderHint(QPainter::Antialiasing);
  painter.setClipRect(x0, y0, size, size);
  QFont font = painter.font();
  font.setPixelSize(std::max(9, size / 60));
  painter.setFont(font);
  const double tolerance = 0.01 * panel.halfSize;  // a marker on the surface is not hidden by it
  for (const PreviewMarker& m : markers) {
    const Eigen::Vector3d p = project(m.position);
    const int px = static_cast<int>(std::floor(p.x())), py = static_cast<int>(std::floor(p.y()));
    if (px < 0 || py < 0 || px >= size || py >= size) continue;
    const bool hidden = depth[static_cast<std::size_t>(py) * static_cast<std::size_t>(size) +
                              static_cast<std::size_t>(px)] > p.z() + tolerance;
    const QPointF at(x0 + p.x(), y0 + p.y());
    painter.setPen(QPen(hidden ? m.colour : QColor(Qt::black), 1.0));
    painter.setBrush(hidden ? QBrush(Qt::NoBrush) : QBrush(m.colour));
    painter.drawEllipse(at, 3.5, 3.5);
    painter.setPen(hidden ? QColor(90, 90, 90) : QColor(Qt::black));
    painter.drawText(at + QPointF(5, -4), m.label);
  }
  painter.setPen(Qt::black);
  font.setPixelSize(std::max(12, size / 40));
  painter.setFont(font);
  painter.drawText(QPointF(x0 + 8, y0 + 8 + font.pixelSize()), panel.title);
  painter.setPen(QColor(160, 160, 160));
  painter.setBrush(Qt::NoBrush);  // a frame, not a fill over the panel
  painter.drawRect(x0, y0, size - 1, size - 1);
}

}  // namespace

QImage renderHeadPreview(const HeadMesh& mesh, const Eigen::Matrix3Xf& positions,
                         const std::vector<PreviewPanel>& panels,
                         const std::vector<PreviewMarker>& markers, const PreviewStyle& style) {
  // A grid at most three panels wide keeps the image close to square, so viewers that shrink
  // wide images still show the labels.
  const int count = std::max<int>(1, static_cast<int>(panels.size()));
  const int columns = std::min(count, 3), rows = (count + columns - 1) / columns;
  QImage image(style.panelSize * columns, style.panelSize * rows, QImage::Format_RGB32);
  image.fill(QColor(235, 240, 245));
  const std::vector<QImage> textures = loadTextures(mesh, style.textured);
  for (std::size_t k = 0; k < panels.size(); ++k)
    renderPanel(image, static_cast<int>(k) % columns * style.panelSize,
                static_cast<int>(k) / columns * style.panelSize, mesh, positions, panels[k],
                markers, style, textures);
  return image;
}

}  // namespace lacrima::exporters
