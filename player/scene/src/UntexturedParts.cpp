#include <lacrima/scene/UntexturedParts.h>

#include <Eigen/Geometry>
#include <QColor>
#include <QPainter>
#include <QRadialGradient>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <string>

namespace lacrima::scene {
namespace {

bool textured(const HeadMesh& head, const HeadSubmesh& part) {
  return part.material >= 0 && part.material < static_cast<int>(head.materials.size()) &&
         !head.materials[static_cast<std::size_t>(part.material)].diffuseTexture.empty();
}

// Plain greys are what importers give parts with no material of their own.
bool grey(const Eigen::Vector4f& colour) {
  const Eigen::Vector3f rgb = colour.head<3>();
  return rgb.maxCoeff() - rgb.minCoeff() < 0.05f;
}

std::string lower(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

bool isCornea(const HeadSubmesh& part) {
  return part.name == "cornea_l" || part.name == "cornea_r";
}

}  // namespace

int eyeSideOf(const HeadSubmesh& part) {
  if (part.name == "eye_l" || part.name == "cornea_l" || part.role == "eye_left") return 0;
  if (part.name == "eye_r" || part.name == "cornea_r" || part.role == "eye_right") return 1;
  return -1;
}

bool drawsGeneratedEye(const HeadMesh& head, const HeadSubmesh& part) {
  return eyeSideOf(part) >= 0 && !isCornea(part) && !textured(head, part) && part.vertexCount > 0;
}

Eigen::Matrix2Xf drawnUvs(const HeadMesh& head) {
  const Eigen::Index n = head.positions.cols();
  Eigen::Matrix2Xf uvs = head.uvs.cols() == n ? head.uvs : Eigen::Matrix2Xf::Zero(2, n);
  // Each eye's extent over all its generated parts (sclera and iris together), so both map
  // onto one picture of the eye.
  std::array<Eigen::AlignedBox3f, 2> boxes;
  for (const HeadSubmesh& part : head.submeshes)
    if (drawsGeneratedEye(head, part))
      for (int v = part.firstVertex; v < part.firstVertex + part.vertexCount; ++v)
        boxes[static_cast<std::size_t>(eyeSideOf(part))].extend(head.positions.col(v));
  for (const HeadSubmesh& part : head.submeshes) {
    if (!drawsGeneratedEye(head, part)) continue;
    const Eigen::AlignedBox3f& box = boxes[static_cast<std::size_t>(eyeSideOf(part))];
    const Eigen::Vector3f centre = box.center();
    // The eyeball's radius seen from the front (its width and height; its depth may be cut).
    const float radius = std::max(1e-6f, 0.25f * (box.sizes().x() + box.sizes().y()));
    for (int v = part.firstVertex; v < part.firstVertex + part.vertexCount; ++v) {
      const Eigen::Vector3f d = head.positions.col(v) - centre;
      // The back half sees the sclera at the disc's rim, never the iris through the head.
      const float back = d.z() < 0 ? 1.0f : 0.0f;
      Eigen::Vector2f p = d.head<2>() / radius;
      if (back > 0) p = p.normalized() * 0.98f;
      if (!p.allFinite()) p = {0.98f, 0};
      // The picture is round: only its centre (the gaze) and its radius matter; v runs down.
      uvs(0, v) = 0.5f + 0.5f * std::clamp(p.x(), -1.0f, 1.0f);
      uvs(1, v) = 0.5f - 0.5f * std::clamp(p.y(), -1.0f, 1.0f);
    }
  }
  return uvs;
}

QImage generatedEyeTexture(int size) {
  QImage image(size, size, QImage::Format_RGB32);
  image.fill(QColor(232, 226, 220));  // sclera: warm off-white
  QPainter p(&image);
  p.setRenderHint(QPainter::Antialiasing);
  const QPointF c(size / 2.0, size / 2.0);
  const double disc = size / 2.0;
  // Towards the rim the sclera turns pinker, as it does under the lids.
  QRadialGradient rim(c, disc);
  rim.setColorAt(0.6, QColor(232, 226, 220, 0));
  rim.setColorAt(1.0, QColor(214, 170, 160, 255));
  p.fillRect(image.rect(), rim);
  const double iris = disc * kIrisOfEyeball;
  QRadialGradient irisFill(c, iris);
  irisFill.setColorAt(0.0, QColor(120, 84, 40));
  irisFill.setColorAt(0.55, QColor(98, 70, 38));
  irisFill.setColorAt(0.9, QColor(62, 48, 30));
  irisFill.setColorAt(1.0, QColor(30, 24, 18));  // the dark limbal ring
  p.setPen(Qt::NoPen);
  p.setBrush(irisFill);
  p.drawEllipse(c, iris, iris);
  // Fibres: light and dark spokes from the pupil out.
  for (int k = 0; k < 72; ++k) {
    const double a = k * 2 * M_PI / 72 + 0.03 * std::sin(k * 7.0);
    const QPointF dir(std::cos(a), std::sin(a));
    p.setPen(QPen(k % 2 ? QColor(150, 112, 60, 90) : QColor(40, 28, 16, 70), size / 200.0));
    p.drawLine(c + dir * iris * kPupilOfIris, c + dir * iris * 0.92);
  }
  p.setPen(Qt::NoPen);
  p.setBrush(QColor(8, 8, 10));
  p.drawEllipse(c, iris * kPupilOfIris, iris * kPupilOfIris);
  return image;
}

std::optional<UntexturedKind> untexturedKind(const HeadSubmesh& part,
                                             const HeadMaterial& material) {
  if (!material.diffuseTexture.empty() || !grey(material.diffuse)) return std::nullopt;
  const std::string name = lower(part.name + " " + material.name);
  if (part.role == "skin") return UntexturedKind::Skin;
  if (name.find("teeth") != std::string::npos || name.find("tooth") != std::string::npos)
    return UntexturedKind::Teeth;
  if (part.role == "attached" && name.find("lash") != std::string::npos)
    return UntexturedKind::Lashes;
  return std::nullopt;
}

Eigen::Vector4f untexturedColour(UntexturedKind kind) {
  switch (kind) {
    case UntexturedKind::Skin:
      return {0.86f, 0.67f, 0.56f, 1.0f};
    case UntexturedKind::Teeth:
      return {0.90f, 0.87f, 0.78f, 1.0f};
    case UntexturedKind::Lashes:
      return {0.12f, 0.08f, 0.06f, 0.55f};
  }
  return {0.8f, 0.8f, 0.8f, 1.0f};
}

}  // namespace lacrima::scene
