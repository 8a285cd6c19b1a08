#pragma once
// Comparing two renders in tests: how much of the picture a change of pose, tears or head
// moved. Grey levels, so a colour shift without a change of light does not count; a tolerance
// of a little over 4% of the range, so software rendering's dithering does not either.
#include <QImage>

#include <cstdlib>

namespace lacrima::testsupport {

// Fraction of pixels whose grey level differs by more than 12 (of 255) between two renders of
// one size; 0 when the sizes differ or the first is null.
inline double changedFraction(const QImage& a, const QImage& b) {
  if (a.size() != b.size() || a.isNull()) return 0;
  const QImage x = a.convertToFormat(QImage::Format_RGB32);
  const QImage y = b.convertToFormat(QImage::Format_RGB32);
  long long changed = 0;
  for (int row = 0; row < x.height(); ++row) {
    const auto* p = reinterpret_cast<const QRgb*>(x.constScanLine(row));
    const auto* q = reinterpret_cast<const QRgb*>(y.constScanLine(row));
    for (int col = 0; col < x.width(); ++col)
      if (std::abs(qGray(p[col]) - qGray(q[col])) > 12) ++changed;
  }
  return static_cast<double>(changed) / (static_cast<double>(x.width()) * x.height());
}

}  // namespace lacrima::testsupport
