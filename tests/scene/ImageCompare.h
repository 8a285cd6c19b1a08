#pragma once
// Pixel comparisons for the scene tests.
#include <QImage>
#include <QPoint>
#include <QPointF>
#include <QRect>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <vector>

namespace lacrima::scenetest {

// Largest channel difference of one pixel (RGB, 0..255).
inline int channelDifference(const QImage& a, const QImage& b, int x, int y) {
  const uchar* p = a.constScanLine(y) + 4 * x;
  const uchar* q = b.constScanLine(y) + 4 * x;
  return std::max({std::abs(p[0] - q[0]), std::abs(p[1] - q[1]), std::abs(p[2] - q[2])});
}

// Pixels whose colour differs by more than `threshold` in some channel (same-size RGBA8888).
inline std::vector<QPoint> differingPixels(const QImage& a, const QImage& b, int threshold) {
  std::vector<QPoint> out;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x)
      if (channelDifference(a, b, x, y) > threshold) out.emplace_back(x, y);
  return out;
}

struct MeanColour {
  double r = 0, g = 0, b = 0;
  double luminance() const { return 0.2126 * r + 0.7152 * g + 0.0722 * b; }
  double redness() const { return r / std::max(1.0, 0.5 * (g + b)); }  // red over the other two
};

// Mean colour of the (2 half + 1)^2 window around `centre`, clipped to the image.
inline MeanColour meanColour(const QImage& image, QPointF centre, int half) {
  MeanColour m;
  int n = 0;
  const int cx = static_cast<int>(std::lround(centre.x())),
            cy = static_cast<int>(std::lround(centre.y()));
  for (int y = std::max(0, cy - half); y <= std::min(image.height() - 1, cy + half); ++y)
    for (int x = std::max(0, cx - half); x <= std::min(image.width() - 1, cx + half); ++x) {
      const uchar* p = image.constScanLine(y) + 4 * x;
      m.r += p[0];
      m.g += p[1];
      m.b += p[2];
      ++n;
    }
  if (n > 0) {
    m.r /= n;
    m.g /= n;
    m.b /= n;
  }
  return m;
}

}  // namespace lacrima::scenetest
