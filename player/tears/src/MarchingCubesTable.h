#pragma once
// The 256-case marching-cubes table, generated from the cube's topology instead of typed in.
//
// Conventions (shared by the table and the mesher):
//  * corner k (0..7) of a cube sits at offset (k & 1, (k >> 1) & 1, (k >> 2) & 1) lattice steps;
//  * edge e (0..11) runs along axis a = e / 4; its two other corner bits are taken from
//    r = e % 4 as (bit of axis (a+1)%3) = r & 1 and (bit of axis (a+2)%3) = r >> 1. Its lower
//    corner has bit a = 0, the upper corner bit a = 1;
//  * the configuration index has bit k set when corner k is INSIDE (colour >= iso).
//
// Generation: on each of the six faces, the iso contour is decided by the face's four corner
// signs alone, with a fixed rule for the ambiguous face (two diagonal corners inside, two
// outside): the inside corners are kept SEPARATE. A face is shared by two cubes that see the
// same four signs, so both produce the same contour on it and the surface has no cracks, with
// no per-cube disambiguation. The face contours are directed segments (inside on their left as
// seen from outside the cube); each crossing edge is the end of exactly one segment and the
// start of one, so they chain into closed loops, which are fanned into triangles wound
// counter-clockwise when seen from outside the fluid (normals by the right-hand rule point out).
// Fan diagonals never join two crossings that lie on one face: such a diagonal could also be
// chosen by the cube on the other side, and the edge would then have four triangles.
#include <array>
#include <cstdint>

namespace lacrima::tears {

struct MarchingCubesCase {
  static constexpr int kMaxTriangles = 8;  // the generated table needs 5
  int triangleCount = 0;
  std::array<std::int8_t, 3 * kMaxTriangles> edges{};  // three cube edges per triangle
};

class MarchingCubesTable {
 public:
  static const MarchingCubesTable& instance();

  const MarchingCubesCase& operator[](int configuration) const {
    return cases_[static_cast<std::size_t>(configuration)];
  }
  // Lower and upper corner of edge e.
  static int edgeLowerCorner(int edge);
  static int edgeUpperCorner(int edge) { return edgeLowerCorner(edge) | (1 << edgeAxis(edge)); }
  static int edgeAxis(int edge) { return edge >> 2; }

 private:
  MarchingCubesTable();
  std::array<MarchingCubesCase, 256> cases_;
};

}  // namespace lacrima::tears
