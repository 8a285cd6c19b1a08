#pragma once
// Where a rigged head can reach, for culling bounds that never hide a deformed face.
#include <lacrima/common/HeadMesh.h>
#include <lacrima/common/PoseSet.h>
#include <lacrima/exporters/RigExport.h>

#include <Eigen/Geometry>

#include <vector>

namespace lacrima::exporters {

// A box containing every vertex for every combination of FAP values where each exported pose's
// channel lies within rangeFactor times its slider range (0 always included), eyeballs turned
// any way about their centres and the head turned any way about its pivot. Poses are linear
// and independent, so summing each pose's extreme per vertex and axis bounds all combinations;
// rotations are covered by the sphere they can sweep. Conservative, not tight.
Eigen::AlignedBox3f reachableBounds(const HeadMesh& head, const PoseSet& poses,
                                    const std::vector<ExportedPose>& exported, float rangeFactor);

}  // namespace lacrima::exporters
