#pragma once
// A small head-like mesh made in the test, for suites that must run without ../shared or the
// default head: an ellipsoid about a head's size in millimetres (x across, y up, z forward),
// closed, with one vertex per point (single poles, rings that wrap without a seam copy), so an
// importer that merges identical vertices keeps every one.
#include <Eigen/Core>

#include <QFile>
#include <QString>

#include <cmath>
#include <numbers>
#include <vector>

namespace lacrima::testsupport {

struct GeneratedHead {
  std::vector<Eigen::Vector3f> positions;
  std::vector<Eigen::Vector3i> triangles;  // counter-clockwise seen from outside
  Eigen::Vector3f radii;
};

// `rings` bands from the top pole to the bottom one, `segments` vertices around each ring.
inline GeneratedHead generatedHead(int rings = 12, int segments = 16,
                                   Eigen::Vector3f radii = {75.0f, 110.0f, 95.0f}) {
  GeneratedHead head;
  head.radii = radii;
  head.positions.emplace_back(0.0f, radii.y(), 0.0f);
  for (int r = 1; r < rings; ++r) {
    const double polar = std::numbers::pi * r / rings;
    for (int s = 0; s < segments; ++s) {
      const double around = 2 * std::numbers::pi * s / segments;
      head.positions.emplace_back(
          static_cast<float>(radii.x() * std::sin(polar) * std::sin(around)),
          static_cast<float>(radii.y() * std::cos(polar)),
          static_cast<float>(radii.z() * std::sin(polar) * std::cos(around)));
    }
  }
  const int bottom = static_cast<int>(head.positions.size());
  head.positions.emplace_back(0.0f, -radii.y(), 0.0f);
  const auto at = [segments](int ring, int s) { return 1 + (ring - 1) * segments + s % segments; };
  for (int s = 0; s < segments; ++s) {
    head.triangles.emplace_back(0, at(1, s), at(1, s + 1));
    for (int r = 1; r + 1 < rings; ++r) {
      head.triangles.emplace_back(at(r, s), at(r + 1, s), at(r + 1, s + 1));
      head.triangles.emplace_back(at(r, s), at(r + 1, s + 1), at(r, s + 1));
    }
    head.triangles.emplace_back(at(rings - 1, s), bottom, at(rings - 1, s + 1));
  }
  return head;
}

// Writes `head` as a Wavefront OBJ (one object, 1-based faces); false when the file cannot be.
inline bool writeObj(const GeneratedHead& head, const QString& path) {
  QFile file(path);
  if (!file.open(QIODevice::WriteOnly | QIODevice::Text)) return false;
  QByteArray text = "o generated_head\n";
  for (const Eigen::Vector3f& p : head.positions)
    text += "v " + QByteArray::number(p.x()) + ' ' + QByteArray::number(p.y()) + ' ' +
            QByteArray::number(p.z()) + '\n';
  for (const Eigen::Vector3i& t : head.triangles)
    text += "f " + QByteArray::number(t[0] + 1) + ' ' + QByteArray::number(t[1] + 1) + ' ' +
            QByteArray::number(t[2] + 1) + '\n';
  return file.write(text) == text.size();
}

}  // namespace lacrima::testsupport
