#pragma once
// Turning faces of a three.js model into a HeadMesh sub-mesh.
#include "ThreeJsonModel.h"

#include <lacrima/common/HeadMesh.h>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace lacrima::rigging {

// Appends the faces `faceIndices` of `model`, placed at `positions` (the model's own vertices
// or a proxy's fitted ones), to `mesh` as a new sub-mesh. Every distinct (vertex, uv) pair of a
// corner becomes one vertex, in order of first use: a uv seam thus becomes coincident copies,
// which HeadMesh::computeNormals welds. Quads become triangles (0,1,2) and (0,2,3), which keeps
// MakeHuman's counter-clockwise winding; uvs are stored as (u, 1 - v) for OGRE, whose texture
// origin is the top-left corner. Normals are left to the caller (computeNormals once at the end).
// Throws FileError naming the model when a face has no uvs.
void appendSubmesh(HeadMesh& mesh, const std::string& name, int material, const ThreeModel& model,
                   const Eigen::Matrix3Xf& positions, const std::vector<int>& faceIndices);

}  // namespace lacrima::rigging
