#include <lacrima/tears/SyntheticSkin.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace lacrima::tears {

SyntheticSkin makeCheekSheet(const CheekSheetOptions& o) {
  const int columns = std::max(2, static_cast<int>(std::ceil(o.width / o.edge))) + 1;
  const int rows = std::max(2, static_cast<int>(std::ceil(o.height / o.edge))) + 1;
  const double tilt = o.tiltDegrees * std::numbers::pi / 180.0;
  const Eigen::AngleAxisd lean(-tilt, Eigen::Vector3d::UnitX());  // top moves towards -z
  auto surfacePoint = [&](double u, double v) {                   // u across, v up, both centred
    const double angle = u / o.cylinderRadius;
    const Eigen::Vector3d flat(o.cylinderRadius * std::sin(angle), v,
                               o.cylinderRadius * (std::cos(angle) - 1.0));
    return Eigen::Vector3d(lean * flat);
  };

  SyntheticSkin sheet;
  sheet.positions.resize(3, columns * rows);
  for (int r = 0; r < rows; ++r) {
    const int sourceRow = (o.collapsedRow && r == rows / 2) ? r - 1 : r;  // zero-area strip
    const double v = -0.5 * o.height + o.height * sourceRow / (rows - 1);
    for (int c = 0; c < columns; ++c) {
      const double u = -0.5 * o.width + o.width * c / (columns - 1);
      sheet.positions.col(r * columns + c) = surfacePoint(u, v).cast<float>();
    }
  }
  for (int r = 0; r + 1 < rows; ++r)
    for (int c = 0; c + 1 < columns; ++c) {
      const int a = r * columns + c, b = a + 1, d = a + columns, e = d + 1;
      sheet.triangles.emplace_back(a, b, e);  // counter-clockwise from +z (u right, v up)
      sheet.triangles.emplace_back(a, e, d);
    }
  for (int k = 0; k < o.extraDegenerateTriangles; ++k) {
    const int r = 1 + (k * 7) % (rows - 2), c = 1 + (k * 13) % (columns - 2);
    const int a = r * columns + c;
    if (k % 2 == 0)
      sheet.triangles.emplace_back(a, a, a + 1);  // repeated vertex
    else
      sheet.triangles.emplace_back(a - 1, a, a + 1);  // three points of one row: nearly collinear
  }

  Eigen::AlignedBox3d box;
  for (Eigen::Index i = 0; i < sheet.positions.cols(); ++i)
    box.extend(sheet.positions.col(i).cast<double>());
  sheet.centre = box.center();
  sheet.radius = 0.5 * box.sizes().y();
  // Sources 0.3 dm either side of the middle, 0.25 dm below the top edge, slightly in front.
  const Eigen::Vector3d normalNearTop = lean * Eigen::Vector3d::UnitZ();
  const double v = 0.5 * o.height - 0.25;
  sheet.leftSource = surfacePoint(0.3, v) + 0.01 * normalNearTop;
  sheet.rightSource = surfacePoint(-0.3, v) + 0.01 * normalNearTop;
  return sheet;
}

SyntheticSkin makeChinSphere(const ChinSphereOptions& o) {
  const double pi = std::numbers::pi;
  // Rings of constant angle about the x axis (polar angle theta from +x), each with the same
  // number of segments around it (phi, in the y-z plane): pole caps are fans.
  const int rings = std::max(4, static_cast<int>(std::ceil(pi * o.radius / o.edge)));
  const int segments = std::max(6, static_cast<int>(std::ceil(2 * pi * o.radius / o.edge)));
  auto point = [&](double theta, double phi) {
    return Eigen::Vector3d(o.radius * std::cos(theta), o.radius * std::sin(theta) * std::cos(phi),
                           o.radius * std::sin(theta) * std::sin(phi));
  };
  SyntheticSkin sphere;
  const int inner = rings - 1;  // rings of vertices between the poles
  sphere.positions.resize(3, inner * segments + 2);
  for (int r = 0; r < inner; ++r)
    for (int s = 0; s < segments; ++s)
      sphere.positions.col(r * segments + s) =
          point(pi * (r + 1) / rings, 2 * pi * s / segments).cast<float>();
  const int north = inner * segments, south = north + 1;  // theta = 0 (+x) and pi (-x)
  sphere.positions.col(north) = Eigen::Vector3f(static_cast<float>(o.radius), 0, 0);
  sphere.positions.col(south) = Eigen::Vector3f(static_cast<float>(-o.radius), 0, 0);
  // Counter-clockwise seen from outside: with theta growing towards -x and phi turning from
  // +y to +z, (d theta) x (d phi) points outward.
  auto at = [&](int r, int s) { return r * segments + (s % segments); };
  for (int s = 0; s < segments; ++s) {
    sphere.triangles.emplace_back(north, at(0, s), at(0, s + 1));
    for (int r = 0; r + 1 < inner; ++r) {
      sphere.triangles.emplace_back(at(r, s), at(r + 1, s), at(r + 1, s + 1));
      sphere.triangles.emplace_back(at(r, s), at(r + 1, s + 1), at(r, s + 1));
    }
    sphere.triangles.emplace_back(at(inner - 1, s), south, at(inner - 1, s + 1));
  }
  sphere.centre = Eigen::Vector3d::Zero();
  sphere.radius = o.radius;
  const double latitude = o.sourceDegrees * pi / 180, side = 0.05 * o.radius;
  for (auto [source, x] :
       {std::pair{&sphere.leftSource, side}, std::pair{&sphere.rightSource, -side}}) {
    const Eigen::Vector3d onFront(x, o.radius * std::sin(latitude), o.radius * std::cos(latitude));
    *source = onFront.normalized() * o.radius * 1.01;
  }
  return sphere;
}

Eigen::Matrix3Xf movedSheet(const SyntheticSkin& sheet, const Eigen::Vector3d& translation,
                            const Eigen::AngleAxisd& rotation) {
  Eigen::Matrix3Xf out(3, sheet.positions.cols());
  const Eigen::Matrix3d R = rotation.toRotationMatrix();
  for (Eigen::Index i = 0; i < sheet.positions.cols(); ++i) {
    const Eigen::Vector3d x = sheet.positions.col(i).cast<double>();
    out.col(i) = (sheet.centre + R * (x - sheet.centre) + translation).cast<float>();
  }
  return out;
}

}  // namespace lacrima::tears
