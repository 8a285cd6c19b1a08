#pragma once
// How attached sub-meshes (eyelashes, eyebrows: cards that sit just off the skin) follow it.
//
// Each attached vertex v is bound once, on the neutral head, to the closest point x_v of the
// skin surface (closestSurfacePoints): a skin triangle (c_0, c_1, c_2) and barycentric b_v.
// For every skin feature point's influence w, v gets
//   w(v) = b_v0 w(c_0) + b_v1 w(c_1) + b_v2 w(c_2),
// the weight the surface has at x_v. Poses are linear in the weights (d = w * step), so under
// every FAP v moves exactly as x_v does, and keeps its rest offset v - x_v: the card rides on
// the skin under it instead of copying one vertex, which between vertices, or across a fold,
// moves differently from that skin and lifts the card off it.
//
// The offset is carried, not turned: the skin's poses are translations, and where they tilt
// the surface under a card the offset keeps its rest direction. docs/rig.md gives what that
// costs on the default head (tests/rigging/AttachedCardsTest.cpp measures it).
#include <lacrima/common/HeadMesh.h>
#include <lacrima/common/PoseBaking.h>

#include <Eigen/Core>

#include <string>
#include <utility>
#include <vector>

namespace lacrima::rigging {

struct SkinAttachment {
  std::vector<int> vertices;                 // the attached vertices
  std::vector<Eigen::Vector3i> corners;      // per attached vertex: its skin triangle's corners
  std::vector<Eigen::Vector3d> barycentric;  // per attached vertex: b_v, weights of the corners

  // (v, w(v)) for every attached vertex the skin influence reaches (w(v) > 0).
  std::vector<std::pair<int, float>> weights(const FeaturePointInfluence& skin) const;
};

// Binds `attached` (global vertices) to the triangles of the `skin` sub-meshes. A vertex finds
// no skin only when the skin has no triangle of positive area; it is then left unbound.
SkinAttachment attachToSkin(const HeadMesh& mesh, const std::vector<std::string>& skin,
                            const std::vector<int>& attached);

}  // namespace lacrima::rigging
