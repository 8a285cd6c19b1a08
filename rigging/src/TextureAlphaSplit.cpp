#include "TextureAlphaSplit.h"

#include <lacrima/common/Diagnostics.h>

#include <QImage>
#include <QImageReader>
#include <QString>

#include <algorithm>
#include <cmath>

namespace lacrima::rigging {

std::vector<bool> transparentAtUvCentre(const ThreeModel& model,
                                        const std::vector<int>& faceIndices,
                                        const std::string& texturePath) {
  QImageReader reader(QString::fromStdString(texturePath));
  const QImage image = reader.read();
  if (image.isNull())
    throw FileError(SourceLocation{texturePath},
                    "cannot read the image: " + reader.errorString().toStdString());
  if (!image.hasAlphaChannel())
    throw FileError(SourceLocation{texturePath},
                    "expected an image with an alpha channel (transparent parts mark the cornea)");

  std::vector<bool> transparent;
  transparent.reserve(faceIndices.size());
  for (int f : faceIndices) {
    const ThreeFace& face = model.faces[static_cast<size_t>(f)];
    Eigen::Vector2f centre = Eigen::Vector2f::Zero();
    for (int c = 0; c < face.corners; ++c) {
      const int uv = face.uv[static_cast<size_t>(c)];
      if (uv < 0)
        throw FileError(SourceLocation{model.path},
                        "face " + std::to_string(f) + " has no uvs (expected per-corner uvs)");
      centre += model.uvs.col(uv);
    }
    centre /= static_cast<float>(face.corners);
    // Repeat outside [0, 1] as a renderer would; v points up, image rows go down.
    const float u = centre.x() - std::floor(centre.x());
    const float v = centre.y() - std::floor(centre.y());
    const int x =
        std::clamp(static_cast<int>(u * static_cast<float>(image.width())), 0, image.width() - 1);
    const int y = std::clamp(static_cast<int>((1.0f - v) * static_cast<float>(image.height())), 0,
                             image.height() - 1);
    transparent.push_back(qAlpha(image.pixel(x, y)) < 128);
  }
  return transparent;
}

}  // namespace lacrima::rigging
