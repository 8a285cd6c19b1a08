#pragma once
// The feature-aware part of proposing feature points (FeaturePointProposal.h, step 3): the points
// on and around the eyes placed from the eyes rather than from the face's warp.
//
// The spline carries the whole face smoothly, but an eye is a rigid ball whose centre both
// heads have (given or fitted, and an anchor of the warp): a point on it keeps its direction
// from the centre, whatever the face around it does. So
//   (1) a point on an eye (the pupil 3.5 / 3.6) is carried rigidly about the eye's centre and
//       put on the eye's outer surface (the cornea over the pupil: the pupil is a hole in the
//       iris, with no vertex at its centre),
//         x' = c' + a' Q s R (x - c) / |s R (x - c)|,
//       c, c' the eye's centre on the reference and the new head, s R the anchors' similarity,
//       a' the new cornea's apex distance from c', and Q the least rotation that takes the
//       reference eye's gaze, so carried, onto the new eye's (an eye may look a little outward:
//       the ICT head's do, by about 5 degrees). An eye's gaze runs from its centre to the middle
//       of its cornea, the cap of its front half that bulges out of the eyeball's sphere;
//       without a bulge of 3% of the radius, or with a gaze 30 degrees off the carried one,
//       Q = I and a' = |s R (x - c)|;
//   (2) the lid points the standard puts above and below the pupil (3.1, 3.3, 3.9, 3.13 on the
//       left, 3.2, 3.4, 3.10, 3.14 on the right) are moved along the face's left-right axis
//       l = R e_x onto the pupil's vertical plane,
//         x' = x + l (l . (p - x)),   p the pupil (given, or from (1)),
//       because IRISD0, the distance 3.1-3.3, is the iris' diameter only when the lids straddle
//       the pupil (the lids tangent to the iris in the neutral face);
//   (3) and a lid point that is then inside the eye, nearer its centre than the cornea's apex,
//       is pushed out along its direction from the centre to the apex distance: a lid rests on
//       the eye, and the warp, which knows nothing of the eye being solid, had left the ICT
//       head's lid points a tenth of the eye's radius inside it, where the snap took the lining
//       tucked behind the eyeball instead of the lid's margin.
// On the ICT head the warp alone put the pupils 2.4 mm from the pupil's centre, and the upper
// lids 3.4 mm from their margins; with this step the pupils are on the vertex over the pupil's
// centre and the lids within 1.5 mm.
//
// All three are similarity-invariant: they use only the anchors' similarity and the eyes' centres
// and shapes. The reference head must be in the face frame (+x its own left, +y up, +z forward), as
// the default head is.
#include <lacrima/common/HeadMesh.h>
#include <lacrima/rigging/FeaturePointFile.h>

#include <Eigen/Core>

#include <map>
#include <string>
#include <vector>

namespace lacrima::rigging {

struct EyeCentrePair {
  Eigen::Vector3d reference, head;
};
using EyeCentres = std::map<std::string, EyeCentrePair>;  // by side: "eye_left", "eye_right"

// Moves the proposed points `ids` (column k of `carried` is point ids[k] on the new head, after
// the warp) as (1) and (2) above. `rotation` and `scale` are the anchors' similarity R and s;
// an eye missing from `eyes` leaves its points as the warp put them.
void placeEyePoints(const std::vector<std::string>& ids, const FeaturePointFile& reference,
                    const HeadMesh& referenceMesh, const FeaturePointFile& partial,
                    const HeadMesh& mesh, const EyeCentres& eyes, const Eigen::Matrix3d& rotation,
                    double scale, Eigen::Matrix3Xd& carried);

}  // namespace lacrima::rigging
