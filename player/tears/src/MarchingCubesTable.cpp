#include "MarchingCubesTable.h"

#include <stdexcept>
#include <vector>

namespace lacrima::tears {
namespace {

int bitOf(int corner, int axis) { return (corner >> axis) & 1; }

// The edge joining two corners that differ in exactly one bit.
int edgeBetween(int p, int q) {
  const int differ = p ^ q;
  const int axis = differ == 1 ? 0 : (differ == 2 ? 1 : 2);
  const int b = (axis + 1) % 3, c = (axis + 2) % 3;
  return axis * 4 + bitOf(p, b) + 2 * bitOf(p, c);
}

// Faces are (axis, side); an edge of axis a with other bits (rb, rc) lies on faces
// ((a+1)%3, rb) and ((a+2)%3, rc). Two edges lie on a common face iff these sets meet.
bool shareFace(int e1, int e2) {
  auto faces = [](int e) {
    const int a = e >> 2, r = e & 3;
    return std::array<int, 2>{((a + 1) % 3) * 2 + (r & 1), ((a + 2) % 3) * 2 + (r >> 1)};
  };
  const auto f1 = faces(e1), f2 = faces(e2);
  return f1[0] == f2[0] || f1[0] == f2[1] || f1[1] == f2[0] || f1[1] == f2[1];
}

// Corners of face (axis, side) counter-clockwise as seen from outside the cube. With
// (a, b, c) right-handed, the view from +a sees (b, c) = (0,0), (1,0), (1,1), (0,1)
// counter-clockwise; the view from -a sees the mirror image, so the order is reversed.
std::array<int, 4> faceCorners(int axis, int side) {
  const int b = (axis + 1) % 3, c = (axis + 2) % 3;
  static constexpr int kPlus[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  static constexpr int kMinus[4][2] = {{0, 0}, {0, 1}, {1, 1}, {1, 0}};
  std::array<int, 4> corners{};
  for (int i = 0; i < 4; ++i) {
    const int* bc = side ? kPlus[i] : kMinus[i];
    corners[static_cast<std::size_t>(i)] = (side << axis) | (bc[0] << b) | (bc[1] << c);
  }
  return corners;
}

// Triangulates the loop so that no diagonal joins two edges of one face. Fans are tried first
// (from every apex); if none qualifies, any triangulation is searched recursively (loops have at
// most 12 vertices). Returns false if the loop admits none.
bool triangulate(const std::vector<int>& loop, std::vector<std::array<int, 3>>& out) {
  const int n = static_cast<int>(loop.size());
  auto diagonalOk = [&](int i, int j) {
    const int d = (j - i + n) % n;
    if (d == 1 || d == n - 1) return true;  // a loop edge, on a face by construction
    return !shareFace(loop[static_cast<std::size_t>(i)], loop[static_cast<std::size_t>(j)]);
  };
  for (int apex = 0; apex < n; ++apex) {
    bool ok = true;
    for (int k = 2; k < n - 1 && ok; ++k) ok = diagonalOk(apex, (apex + k) % n);
    if (!ok) continue;
    for (int k = 1; k + 1 < n; ++k)
      out.push_back({loop[static_cast<std::size_t>(apex)],
                     loop[static_cast<std::size_t>((apex + k) % n)],
                     loop[static_cast<std::size_t>((apex + k + 1) % n)]});
    return true;
  }
  // General case: the polygon v0..v(n-1); pick the triangle on edge (v0, v(n-1)) with apex k,
  // then triangulate both sides.
  if (n == 3) return false;  // a triangle has no diagonals: handled by the fan above
  for (int k = 1; k < n - 1; ++k) {
    if (!diagonalOk(0, k) || !diagonalOk(k, n - 1)) continue;
    std::vector<int> left(loop.begin(), loop.begin() + k + 1);
    std::vector<int> right(loop.begin() + k, loop.end());
    right.push_back(loop.front());
    std::vector<std::array<int, 3>> trial{
        {loop[0], loop[static_cast<std::size_t>(k)], loop.back()}};
    if (left.size() >= 3 && !triangulate(left, trial)) continue;
    if (right.size() >= 3 && !triangulate(right, trial)) continue;
    out.insert(out.end(), trial.begin(), trial.end());
    return true;
  }
  return false;
}

MarchingCubesCase generate(int configuration) {
  auto inside = [&](int corner) { return (configuration >> corner) & 1; };
  std::array<int, 12> next;
  next.fill(-1);
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      const auto q = faceCorners(axis, side);
      for (int i = 0; i < 4; ++i) {
        // A run of inside corners starts at q[i]: enter through edge (q[i-1], q[i]), walk to its
        // last corner q[j], leave through (q[j], q[j+1]). The segment exit -> entry closes the
        // run counter-clockwise; an ambiguous face has two single-corner runs (kept separate).
        const int previous = q[static_cast<std::size_t>((i + 3) % 4)];
        if (!inside(q[static_cast<std::size_t>(i)]) || inside(previous)) continue;
        int j = i;
        while (inside(q[static_cast<std::size_t>((j + 1) % 4)])) j = (j + 1) % 4;
        const int entry = edgeBetween(previous, q[static_cast<std::size_t>(i)]);
        const int exit =
            edgeBetween(q[static_cast<std::size_t>(j)], q[static_cast<std::size_t>((j + 1) % 4)]);
        if (next[static_cast<std::size_t>(exit)] != -1)
          throw std::logic_error("marching cubes: edge leaves twice");
        next[static_cast<std::size_t>(exit)] = entry;
      }
    }
  MarchingCubesCase result;
  std::array<bool, 12> used{};
  for (int start = 0; start < 12; ++start) {
    if (next[static_cast<std::size_t>(start)] < 0 || used[static_cast<std::size_t>(start)])
      continue;
    std::vector<int> loop;
    for (int e = start; !used[static_cast<std::size_t>(e)]; e = next[static_cast<std::size_t>(e)]) {
      used[static_cast<std::size_t>(e)] = true;
      loop.push_back(e);
      if (next[static_cast<std::size_t>(e)] < 0)
        throw std::logic_error("marching cubes: open contour");
    }
    std::vector<std::array<int, 3>> triangles;
    if (loop.size() < 3 || !triangulate(loop, triangles))
      throw std::logic_error("marching cubes: untriangulable loop");
    for (const auto& t : triangles) {
      if (result.triangleCount >= MarchingCubesCase::kMaxTriangles)
        throw std::logic_error("marching cubes: too many triangles");
      // The loop runs with the inside on its left seen from outside the cube, which makes it
      // clockwise seen from outside the fluid: store the triangles reversed.
      const auto base = static_cast<std::size_t>(3 * result.triangleCount++);
      result.edges[base] = static_cast<std::int8_t>(t[0]);
      result.edges[base + 1] = static_cast<std::int8_t>(t[2]);
      result.edges[base + 2] = static_cast<std::int8_t>(t[1]);
    }
  }
  return result;
}

}  // namespace

int MarchingCubesTable::edgeLowerCorner(int edge) {
  const int a = edge >> 2, r = edge & 3;
  return ((r & 1) << ((a + 1) % 3)) | ((r >> 1) << ((a + 2) % 3));
}

MarchingCubesTable::MarchingCubesTable() {
  for (int c = 0; c < 256; ++c) cases_[static_cast<std::size_t>(c)] = generate(c);
}

const MarchingCubesTable& MarchingCubesTable::instance() {
  static const MarchingCubesTable table;  // thread-safe one-time generation (C++11 statics)
  return table;
}

}  // namespace lacrima::tears
