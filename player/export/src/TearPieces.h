#pragma once
// The tear geometry one frame shows, in the form the exporters write: the water (the surface and
// the drops on the skin) and the wet trails, each a triangle mesh in head coordinates. Shared by
// the glTF and the PLY exports, so both write the same tears.
#include <lacrima/playback/FrameView.h>

#include <Eigen/Core>

#include <vector>

namespace lacrima::exporting {

enum class TearKind { Water, Trail };

struct TearPiece {
  TearKind kind = TearKind::Water;
  Eigen::Matrix3Xd positions, normals;
  Eigen::Matrix3Xi triangles;
  Eigen::VectorXd alpha;  // trails: wetness per vertex, 1 fresh .. 0 dry; empty for water
};

// The non-empty meshes of `view`: surface, drops, trails, in that order.
std::vector<TearPiece> tearPieces(const playback::FrameView& view);

}  // namespace lacrima::exporting
