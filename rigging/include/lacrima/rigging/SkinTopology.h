#pragma once
// Checks of the skin surface a rig is built on, and its open boundary (the neck cut).
//
// Geodesic falloff assumes a connected 2-manifold: a skin in several pieces stops influences at
// the gaps (a feature point cannot move a piece it has no surface path to), non-manifold edges
// (three or more triangles on one edge) give distances that jump between sheets, and zero-area
// triangles have no direction. None of these stop a rig, so they are reported as warnings that
// name the sub-meshes, the count and an example triangle, for the user to judge.
// All checks run on the welded surface (uv-seam copies are one point).
#include <lacrima/common/HeadMesh.h>

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

namespace lacrima::rigging {

// Named warnings (empty for a clean skin). Throws std::invalid_argument for an unknown name.
std::vector<std::string> checkSkinTopology(const HeadMesh& mesh,
                                           const std::vector<std::string>& skin);

// The mean of the vertices of the skin's open boundary loop with the lowest mean height (y):
// the neck opening of a head cut from a body. nullopt for a closed skin.
std::optional<Eigen::Vector3d> lowestBoundaryLoopCentre(const HeadMesh& mesh,
                                                        const std::vector<std::string>& skin);

}  // namespace lacrima::rigging
