#pragma once
// Generated surfaces with known geodesic distances, shared by the geodesics tests and the
// `lacrima-bench geodesics` benchmark: an equilateral triangle lattice (flat: geodesic =
// Euclidean distance while the straight segment stays on the surface) and an icosphere
// (geodesic = great-circle angle on the unit sphere).
#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>
#include <map>
#include <utility>
#include <vector>

namespace lacrima::testsurfaces {

struct Surface {
  Eigen::Matrix3Xf positions;
  std::vector<Eigen::Vector3i> triangles;  // counter-clockwise seen from +z / from outside
};

// (columns + 1) vertices per row, rows offset by half a spacing in turn, so every interior
// vertex has six neighbours at 60 degrees: Delaunay, all cotangent weights positive. The
// lattice spans `width` in x and about as much in y, centred on the origin, in the z = 0
// plane.
struct Lattice : Surface {
  int columns = 0, rows = 0;  // vertices are (column 0..columns, row 0..rows)
  double spacing = 0;

  int index(int column, int row) const { return row * (columns + 1) + column; }
  // The vertex nearest the centre.
  int centre() const { return index(columns / 2, rows / 2); }
};

inline Lattice makeLattice(int columns, double width = 2.0) {
  Lattice l;
  l.columns = columns;
  l.spacing = width / columns;
  const double rowHeight = l.spacing * std::sqrt(3.0) / 2;
  l.rows = std::max(1, static_cast<int>(std::lround(width / rowHeight)));
  // Rows alternate between unshifted (even) and shifted right by half a spacing (odd).
  const double cx = 0.5 * (width + 0.5 * l.spacing), cy = 0.5 * l.rows * rowHeight;
  l.positions.resize(3, (l.columns + 1) * (l.rows + 1));
  for (int j = 0; j <= l.rows; ++j)
    for (int i = 0; i <= l.columns; ++i)
      l.positions.col(l.index(i, j)) =
          Eigen::Vector3d((i + 0.5 * (j % 2)) * l.spacing - cx, j * rowHeight - cy, 0.0)
              .cast<float>();
  for (int j = 0; j < l.rows; ++j) {
    for (int i = 0; i < l.columns; ++i) {
      const int a = l.index(i, j), b = l.index(i + 1, j);
      const int c = l.index(i, j + 1), d = l.index(i + 1, j + 1);
      if (j % 2 == 0) {  // upper row shifted right: c sits above the middle of a-b
        l.triangles.emplace_back(a, b, c);
        l.triangles.emplace_back(b, d, c);
      } else {  // lower row shifted right: a sits below the middle of c-d
        l.triangles.emplace_back(a, d, c);
        l.triangles.emplace_back(a, b, d);
      }
    }
  }
  return l;
}

// Gives the triangles between `row` and `row + 1` their own copies of the vertices of `row`
// with column strictly between `fromColumn` and `toColumn`, moved by `offset`. With a zero
// offset the copies coincide with the originals: a uv seam, which welding must undo. With a
// non-zero offset the strip between the two columns becomes a slit whose two lips touch in
// space but meet only at its ends. Returns the copies' indices, in column order.
inline std::vector<int> splitRow(Lattice& l, int row, int fromColumn, int toColumn,
                                 const Eigen::Vector3f& offset) {
  std::map<int, int> copyOf;
  std::vector<int> copies;
  for (int i = fromColumn + 1; i < toColumn; ++i) {
    const int original = l.index(i, row);
    const int copy = static_cast<int>(l.positions.cols());
    l.positions.conservativeResize(3, copy + 1);
    l.positions.col(copy) = l.positions.col(original) + offset;
    copyOf[original] = copy;
    copies.push_back(copy);
  }
  // Triangles above the row are those with a corner in row + 1.
  const int firstAbove = l.index(0, row + 1), lastAbove = l.index(l.columns, row + 1);
  for (Eigen::Vector3i& t : l.triangles) {
    const bool above = ((t.array() >= firstAbove) && (t.array() <= lastAbove)).any();
    if (!above) continue;
    for (int k = 0; k < 3; ++k)
      if (const auto it = copyOf.find(t[k]); it != copyOf.end()) t[k] = it->second;
  }
  return copies;
}

// Icosahedron subdivided `level` times (10 * 4^level + 2 vertices), projected onto the unit
// sphere.
inline Surface makeIcosphere(int level) {
  const double g = (1.0 + std::sqrt(5.0)) / 2;
  std::vector<Eigen::Vector3d> p = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0},
                                    {0, -1, g}, {0, 1, g}, {0, -1, -g}, {0, 1, -g},
                                    {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
  for (Eigen::Vector3d& v : p) v.normalize();
  std::vector<Eigen::Vector3i> t = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                    {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                    {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                    {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int l = 0; l < level; ++l) {
    std::map<std::pair<int, int>, int> midpoint;
    const auto middle = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      if (const auto it = midpoint.find(key); it != midpoint.end()) return it->second;
      p.push_back((p[static_cast<size_t>(a)] + p[static_cast<size_t>(b)]).normalized());
      return midpoint[key] = static_cast<int>(p.size()) - 1;
    };
    std::vector<Eigen::Vector3i> finer;
    for (const Eigen::Vector3i& f : t) {
      const int ab = middle(f[0], f[1]), bc = middle(f[1], f[2]), ca = middle(f[2], f[0]);
      finer.emplace_back(f[0], ab, ca);
      finer.emplace_back(f[1], bc, ab);
      finer.emplace_back(f[2], ca, bc);
      finer.emplace_back(ab, bc, ca);
    }
    t = std::move(finer);
  }
  Surface s;
  s.positions.resize(3, static_cast<Eigen::Index>(p.size()));
  for (size_t i = 0; i < p.size(); ++i)
    s.positions.col(static_cast<Eigen::Index>(i)) = p[i].cast<float>();
  // Orient every triangle outwards, whatever the table's winding.
  for (Eigen::Vector3i& f : t) {
    const Eigen::Vector3d a = p[static_cast<size_t>(f[0])], b = p[static_cast<size_t>(f[1])],
                          c = p[static_cast<size_t>(f[2])];
    if ((b - a).cross(c - a).dot(a + b + c) < 0) std::swap(f[1], f[2]);
  }
  s.triangles = std::move(t);
  return s;
}

// Great-circle distance between two points of the unit sphere (positions renormalised in
// double, so float storage does not bias it).
inline double greatCircle(const Eigen::Vector3f& a, const Eigen::Vector3f& b) {
  const Eigen::Vector3d u = a.cast<double>().normalized(), v = b.cast<double>().normalized();
  return std::atan2(u.cross(v).norm(), u.dot(v));
}

}  // namespace lacrima::testsurfaces
