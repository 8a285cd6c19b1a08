#pragma once
// Pose baking: from feature-point influence weights to one pose per FAP.
//
// For translational FAP i with feature point p, unit u and direction dir_i:
//   d_{i,v} = w_p(v) * unitValue(u) * dir_i
// so a value of 1024 moves p (weight 1) by its FAPU distance X0; w_p is p's influence, or the
// FAP's own when RigInput::fapInfluences has one (e.g. weights stretched along the FAP's
// motion, still 1 at p). uv-seam copies of a vertex
// (same position bit for bit) take the largest weight among the copies, so seams never open
// even when the weights list only one copy. Pupil dilation (29, 30) and tongue roll (47) have
// dedicated poses; eyeball and head rotations become RotationGroups. High-level FAPs and tear
// channels have no pose.
//
// Pupil dilation, per eye: a = unit axis from the eye's centre through its pupil point (3.5
// or 3.6), R = IRISD0 / 2 the iris radius, r_p = R / 3 the neutral pupil radius (the neutral
// face's pupil is a third of the iris), s = IRISD0 / 2048 (half an IRISD step). A vertex of
// that eye's group, in front of the centre ((v - c).a > 0), not on a sub-mesh whose name
// contains "cornea", at distance r from the axis moves away from the axis by
//   s * r / r_p                 for r <= r_p (the pupil disc scales uniformly),
//   s * (R - r) / (R - r_p)     for r_p < r < R (the iris ring tapers to the fixed rim),
// per unit: the pupil's diameter grows by one IRISD step per unit, so the table's slider
// range -300..600 spans a pinpoint to nearly the whole iris without the pupil crossing the rim.
//
// Tongue roll (AU): the tongue is the union of the influences of 6.3 and 6.4 (weights w), or,
// when neither exists, every vertex of the first sub-mesh whose name contains "tongue"
// (w = 1). The midline is x_m = mean x of feature points 6.3 and 6.4, else x of 6.2, else of
// 6.1, else the middle of the tongue's x range. A vertex rises (+y) by
//   w * |x - x_m| * 1e-5 per unit,
// the small-angle lift of a side turning up about the midline by 1e-5 rad.
#include <lacrima/common/Fapu.h>
#include <lacrima/common/HeadMesh.h>
#include <lacrima/common/PoseSet.h>

#include <map>
#include <string>
#include <vector>

namespace lacrima::inline common {

// Sparse weights of one feature point: vertices[k] has weight weights[k] in (0, 1].
// Entries with an index out of range or a weight that is not finite and positive are skipped
// (with a warning); weights above 1 are clamped to 1.
struct FeaturePointInfluence {
  std::vector<int> vertices;
  std::vector<float> weights;
};

struct RigInput {
  const HeadMesh* mesh = nullptr;
  FapuSet fapu;
  std::map<std::string, FeaturePointInfluence> influences;  // by FDP id, e.g. "2.1"
  // By FAP number: replaces its feature point's influence in that FAP's translation pose (a
  // FAP whose influence reaches farther along its own motion, e.g. the brow raises).
  std::map<int, FeaturePointInfluence> fapInfluences;
  std::map<std::string, Eigen::Vector3f> featurePoints;  // neutral positions by FDP id
  RotationGroup eyeLeft, eyeRight;  // vertices of each eyeball (+cornea), centre of rotation
  Eigen::Vector3f neckPivot = Eigen::Vector3f::Zero();
  std::vector<int> headVertices;  // vertices that follow head rotation (default: all)
};

struct PoseBakeReport {
  std::vector<int> bakedFaps;         // FAPs that got a pose or rotation group, ascending
  std::vector<std::string> warnings;  // e.g. "FAP 29: no pupil geometry; pose empty"
};

// Throws std::invalid_argument when input.mesh is null; every other gap in the input leaves
// the affected FAPs without a pose and is reported in `report`.
PoseSet bakePoses(const RigInput& input, PoseBakeReport* report = nullptr);

}  // namespace lacrima::inline common
