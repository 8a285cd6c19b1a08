#pragma once
// The lips' step of proposing feature points (FeaturePointProposal.h, step 4): the inner-lip
// points put on the lip they belong to.
//
// The warp carries the default head's inner-lip points to within a few millimetres of the new
// head's lip line, but the lips meet there: the upper and lower lip's inner edges are a fraction
// of a millimetre apart, so the nearest vertex of the skin is as often on the wrong lip as on
// the right one (on the ICT head 2.3 landed on the upper lip, and opening the jaw did not part
// the rigged lips). Near each other in space, the two lips are far apart along the skin: from
// the upper lip's edge to the nose is a lip's height, to the chin round the mouth's corner or
// through the mouth a mouth's width or more, whether the mouth is an open hole in the skin or
// (as on the ICT head) a bag joined to the lips. So, on the skin's edge graph (seam copies
// welded),
//   (1) g_n(v), g_c(v) are the shortest-path distances (Dijkstra) from the skin vertices
//       nearest the nose tip 9.3 and the chin 2.10;
//   (2) a vertex is on the upper lip's side when g_n(v) < g_c(v), on the lower's otherwise;
//   (3) the upper inner-lip points 2.2, 2.6, 2.7 go to the vertex of the upper side nearest
//       their warped place, the lower ones 2.3, 2.8, 2.9 to the lower side's, among the vertices
//       within kSearchRadius of the mouth's width |8.3 - 8.4| of it.
// Nothing here assumes an axis, a unit or which way is up: the anchors say where the nose and
// the chin are. A lip point with no vertex of its side that near (a mouth modelled welded shut
// at that place, or no lips at all) keeps the plain snap, and a warning says so. The inner
// corners 2.4 / 2.5 are where the lips meet, on both, and keep the plain snap.
#include <lacrima/common/Diagnostics.h>
#include <lacrima/common/HeadMesh.h>

#include <Eigen/Core>

#include <map>
#include <string>
#include <vector>

namespace lacrima::rigging {

// Moves the proposed inner-lip points among `ids` (column k of `carried` is point ids[k]) onto
// the vertices (1) to (3) choose on the sub-meshes `skin` of `mesh`. `anchors` are the given
// points' positions on `mesh` by FDP id (it must hold 8.3, 8.4, 9.3 and 2.10). A point left to
// the plain snap gets a warning naming `path` in `warnings` (if any).
void placeLipPoints(const std::vector<std::string>& ids, const HeadMesh& mesh,
                    const std::vector<std::string>& skin,
                    const std::map<std::string, Eigen::Vector3d>& anchors, const std::string& path,
                    Warnings* warnings, Eigen::Matrix3Xd& carried);

}  // namespace lacrima::rigging
