#pragma once
// Cutting the head off the MakeHuman body along a neck edge loop.
#include "ThreeJsonModel.h"

#include <Eigen/Core>

#include <vector>

namespace lacrima::rigging {

// The faces (indices into `faces`, ascending) of the part of `surface` above a closed quad edge
// loop: the loop starts at `loopVertex` along its most sideways (x) edge and goes straight on
// through every vertex; the part is what a flood fill from the face with the highest vertex
// (+y up) reaches without crossing the loop. A plane cannot do this: MakeHuman's neck loops
// tilt by about 20 degrees, and a horizontal cut leaves spikes.
// Throws std::runtime_error when the loop meets a vertex that is not a regular quad vertex,
// does not close, or does not separate the surface.
std::vector<int> facesAboveEdgeLoop(const Eigen::Matrix3Xf& vertices,
                                    const std::vector<ThreeFace>& faces,
                                    const std::vector<int>& surface, int loopVertex);

}  // namespace lacrima::rigging
