#pragma once
// Rig assembly: a head plus its feature-point file -> the RigInput that bakePoses turns into
// one pose per FAP, and everything the player needs to know about the rig (rig.json).
//
//  - FAPU: computeFapu from 3.1-3.6, 9.15, 2.2, 8.3, 8.4.
//  - Skin points: influenceFalloff(geodesic distance / r) over the skin sub-meshes joined at
//    coincident vertices; r = the point's "radius", else defaultInfluenceRadius (FAPU scale).
//    Method: the point's "geodesics", else RigOptions::geodesics, else the file's default.
//  - Jaw and tongue sub-meshes follow the jaw point 2.1 rigidly (weight 1 in its influence),
//    so opening, thrusting and shifting the jaw carries the lower teeth and the tongue.
//  - FAPs with a fold-free range (foldFreeRange: the brows 31-38) get their own influence,
//    the falloff of the distance stretched along their motion so that it reaches
//    kReachPerDisplacement times the largest displacement of the range ahead and behind
//    (directionalReach; DirectionalGeodesics.h), always by fast marching; across, the point's
//    radius.
//  - Tongue points 6.x get their own falloff over the tongue sub-meshes.
//  - Points on an eye sub-mesh (the pupils 3.5, 3.6) move their whole eye (weight 1), so the
//    eyeball thrusts 27/28 move the eyeball and nothing else.
//  - Attached sub-meshes (eyelashes, eyebrows) take, for every skin point's influence, the
//    weight the skin has at each vertex's closest skin point (barycentric in its triangle;
//    src/SkinAttachment.h), so lashes ride on their lid and brows on the brow skin with their
//    rest offset, never lifting off it.
//  - Eyes: RotationGroups of each eye's vertices about the given centre, else the least-squares
//    sphere through them. Head: every vertex about the neck pivot (7.1).
//  - Tear sources (unless the file gives them): the skin vertex nearest to the lower-lid
//    mid-point 3.3 / 3.4 moved down by IRISD0 / 4, just under the lid margin where tears well up.
#include <lacrima/common/Diagnostics.h>
#include <lacrima/common/Fapu.h>
#include <lacrima/common/HeadMesh.h>
#include <lacrima/common/PoseBaking.h>
#include <lacrima/common/PoseSet.h>
#include <lacrima/rigging/FeaturePointFile.h>
#include <lacrima/rigging/InfluenceWeights.h>

#include <Eigen/Core>

#include <algorithm>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lacrima::rigging {

struct RigOptions {
  // Replaces the file's default method (points with their own "geodesics" keep theirs).
  std::optional<GeodesicMethod> geodesics;
  // Called with the fraction done (0..1) and the current stage, e.g. for a progress bar.
  std::function<void(double fraction, std::string_view stage)> progress;
};

struct TearSource {
  int vertex = -1;  // global skin vertex
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
};

struct BuiltRig {
  FapuSet fapu;
  std::map<std::string, Eigen::Vector3d, FdpIdLess> featurePoints;  // neutral positions
  // Global vertices each point is bound to, with their barycentric weights (1 for a vertex).
  std::map<std::string, std::vector<std::pair<int, double>>, FdpIdLess> bindings;
  std::map<std::string, double, FdpIdLess> radii;            // influence radius used
  std::map<std::string, GeodesicMethod, FdpIdLess> methods;  // geodesic method used
  // FAPs whose pose has its own influence, stretched along the motion, and its reach
  // (input.fapInfluences; InfluenceRadius.h).
  std::map<int, DirectionalReach> reaches;
  std::optional<Eigen::Vector3d> eyeCentreLeft, eyeCentreRight;
  std::optional<double> eyeRadiusLeft, eyeRadiusRight;  // when fitted
  Eigen::Vector3d neckPivot = Eigen::Vector3d::Zero();
  TearSource tearLeft, tearRight;
  std::map<std::string, std::string> roles;  // sub-mesh name -> skin/eye_left/.../rigid
  RigInput input;                            // input.mesh points at the mesh given to buildRig
  PoseSet poses;
  // FAPs this head cannot drive, ascending: a missing eye disables its turns, thrust and pupil
  // (left 23, 25, 27, 29; right 24, 26, 28, 30) and its tears (69 / 70). See "Bad heads" below.
  std::vector<int> disabledFaps;
  std::vector<std::string> warnings;  // rig and bake warnings, each naming its subject

  bool disabled(int fap) const {
    return std::binary_search(disabledFaps.begin(), disabledFaps.end(), fap);
  }
};

// Builds and bakes the rig. `fdp` must have passed validateFeaturePoints for `mesh`; `mesh`
// must outlive the result (input.mesh points at it). Throws FileError naming fdp.path when the
// FAPU points give a non-positive distance (computeFapu's message).
//
// Bad heads build with warnings rather than fail (docs/rig.md "Bad heads"):
//  - No eye on a side (no eye_<side> role, its sub-meshes missing or without vertices, or no
//    centre given and none to fit): that eye's FAPs and its tears are disabled (disabledFaps,
//    one warning "no left eye (...): ... no eyes: tears need ..."); its pupil point, wherever it
//    sits, gets no influence. Tears need the eye: its sub-meshes close the skin's eye opening in
//    the tears' collision surface. The tear source is still computed (rig.json lists it).
//  - A skin in several pieces (lip or ear pieces not welded to the face): each skin point whose
//    influence cannot cross to skin of another piece within half its radius gets a warning
//    naming the pieces; weights stay finite (unreached vertices get none).
//  - Non-manifold edges, duplicate and zero-area triangles: the geodesics stay finite
//    (SurfaceGraph.h, HeatGeodesics.h); nothing is reported.
BuiltRig buildRig(const HeadMesh& mesh, const FeaturePointFile& fdp,
                  const RigOptions& options = {});

}  // namespace lacrima::rigging
