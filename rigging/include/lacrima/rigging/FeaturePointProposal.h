#pragma once
// Proposing feature points for a new head from a few placed by hand: the default
// head's points carried onto the new head.
//
// Given n >= 8 anchors placed on both heads (source a_i on the default head, target b_i on the
// new one; at least the eye corners 3.7, 3.8, 3.11, 3.12, the nose tip 9.3, the mouth corners
// 8.3, 8.4 and the chin 2.10; proposeFeaturePoints adds the eye centres when both heads have
// eyes), every other default point p is carried over in three steps:
//
// 1. A similarity (Umeyama 1991, "Least-squares estimation of transformation parameters between
//    two point patterns"): s, R, t minimising sum |s R a_i + t - b_i|^2, with R from the SVD of
//    the anchors' cross-covariance (a reflection corrected to a rotation) and s from the
//    singular values. It absorbs the heads' units and axis conventions: nothing assumes +y up,
//    the face frame is whatever the anchors say it is.
// 2. A thin-plate spline (Bookstein 1989; in 3-D the biharmonic kernel U(r) = r) through the
//    similarity-fitted anchors a'_i = s R a_i + t:
//      f(x) = x + c + A x + sum_i w_i |x - a'_i|,   f(a'_i) = b_i,   sum_i w_i = 0,
//      sum_i w_i a'_i^T = 0,
//    the smoothest (least bending energy) warp that takes every anchor exactly onto its target,
//    so the proportions of the new face (wider mouth, longer nose) carry to the points between.
//    The kernel is equivariant under similarities, so the result does not depend on the units
//    or axes either. Far from the anchors the spline extrapolates their local differences
//    (on the ICT head, without the eye centres, it put the ears 0.6 ES0 off, the similarity
//    alone 0.15 ES0), so its correction fades with the distance d to the nearest fitted anchor:
//      x' = sRp + t,   p' = x' + exp(-(d / r)^2) (f(x') - x'),   r = 0.5 RMS_i |a'_i - mean a'|,
//    exact at the anchors, the similarity far from them, and still similarity-invariant.
// 3. The eyes (FeaturePointProposalFeatures.h): an eye is a rigid ball, so the pupils are carried
//    rigidly about the eye's centre, along the new eye's own gaze (found from its cornea), onto
//    its cornea; the lid points the standard puts above and below the pupil are moved along the
//    face's left-right axis onto the pupil's vertical plane, and out onto the eye when the warp
//    left them inside it.
// 4. The lips (FeaturePointProposalLips.h): the inner-lip points 2.2, 2.6, 2.7 go to the nearest
//    vertex of the upper lip and 2.3, 2.8, 2.9 to the nearest of the lower one, a vertex being on
//    the upper lip's side when it is nearer the nose tip than the chin along the skin's edges;
//    the nearest skin vertex alone put 2.3 on the upper lip of the ICT head, whose rig then never
//    opened its mouth.
// The point is then snapped to a vertex of the part the default point is on (skin to skin, an
// eye's points to that eye, jaw to jaw, tongue to tongue): the vertex nearest its closest surface
// point, which keeps mirror-image points on mirror-image vertices of a symmetric head whichever
// way its quads were split. A feature point is a vertex of the new head, as a hand-made file
// names it.
//
// Why not more: a non-rigid registration of the default skin onto the new one gives no gain
// (docs/rig.md, "Why this and not a registration"): closest points pull the skin together along
// its normals, which the snap already does, and what is left is along the surface, where two
// heads' files differ in convention (where the brows end, where the chin point sits) rather
// than in shape. Step 3 costs well under a millisecond, step 4 about 20 ms on the ICT head (two
// shortest-path searches over its skin).
#include <lacrima/common/Diagnostics.h>
#include <lacrima/common/HeadMesh.h>
#include <lacrima/rigging/FeaturePointFile.h>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace lacrima::rigging {

// The anchors a partial feature-point file must have.
const std::vector<std::string>& proposalAnchors();

// Steps 1 and 2 above: `points` (3 x m, source frame) carried by the similarity fit and the
// thin-plate spline through `source` -> `target` (3 x n each, n >= 4 not all in one plane).
// Throws std::invalid_argument when the sizes differ or the anchors are degenerate.
Eigen::Matrix3Xd warpPoints(const Eigen::Matrix3Xd& source, const Eigen::Matrix3Xd& target,
                            const Eigen::Matrix3Xd& points);

// The similarity's scale s alone (target units per source unit), e.g. to carry radii.
double similarityScale(const Eigen::Matrix3Xd& source, const Eigen::Matrix3Xd& target);

enum class ProposalMethod {
  Warp,          // steps 1 and 2 alone (the method before step 3; kept for comparison)
  FeatureAware,  // and steps 3 and 4, the eyes and the lips
};

struct ProposalOptions {
  ProposalMethod method = ProposalMethod::FeatureAware;
};

// Milliseconds of each stage, for lacrima-bench proposal.
struct ProposalTimings {
  double fitMs = 0;    // anchors, eye centres, similarity and spline (steps 1 and 2)
  double eyesMs = 0;   // step 3
  double mouthMs = 0;  // step 4, the lips
  double snapMs = 0;   // the snap to the vertices of each part
};

// The partial file `partial` (points placed on `mesh`) completed with every point of `reference`
// (a complete file on `referenceMesh`, e.g. the default head's) that it lacks. Given points are
// kept as they are; every given point the reference also has is an anchor of the warp. A
// reference point whose part the new head lacks (no tongue sub-mesh, say) is left out with a
// warning. Radii of proposed points are scaled by the similarity's scale. Throws FileError naming
// `partial.path` and every missing anchor when one of proposalAnchors() is missing, and naming
// the anchors when they cannot define a warp (two at one place, all on one line or in one
// plane, or not finite). `timings`, when given, receives each stage's milliseconds.
// Precondition: `partial` was validated against `mesh` (FeaturePointSet::Partial) and
// `reference` against `referenceMesh`.
FeaturePointFile proposeFeaturePoints(const FeaturePointFile& partial, const HeadMesh& mesh,
                                      const FeaturePointFile& reference,
                                      const HeadMesh& referenceMesh, Warnings* warnings = nullptr,
                                      const ProposalOptions& options = {},
                                      ProposalTimings* timings = nullptr);

}  // namespace lacrima::rigging
