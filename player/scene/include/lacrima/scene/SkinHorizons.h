#pragma once
// Where the skin shadows itself from a directional light, for any direction, precomputed once
// (horizon mapping, Max 1988, per vertex): for each skin vertex, in 8 sectors of azimuth around
// its normal, the sine of the highest elevation at which other skin is seen within `reach`. A
// light lower than the horizon in its direction is blocked. The lights are fixed to the camera,
// so their directions in the head's frame change as the view orbits; the horizons do not. They
// are what puts the neck under the jaw, the upper lip under the nose and the lids under the
// brow in the key light's shadow (skin.vert).
//
// Sector k is centred on azimuth k x 45 degrees in the vertex's tangent frame (HeadTangents.h):
// 0 along the tangent (+u), 90 along w x cross(normal, tangent) (+v). Skin points (the other
// skin vertices, welded copies skipped) count if they lie in the sector's 45-degree wedge
// between a quarter of `reach` and `reach` away; the sine is dot(q - p, normal) / |q - p|, at
// least 0. Nearer points are the vertex's own fold, which the static occlusion darkens already;
// a shadow from them, per vertex over centimetre-sized triangles, drew wedges along the folds
// (beside the nose). Only the skin has horizons; every other vertex gets 0 (never shadowed).
// Neutral pose: the pose turns the tangent frame in the shader, not the horizons.
#include <lacrima/common/HeadMesh.h>

#include <Eigen/Core>

#include <array>
#include <vector>

namespace lacrima::scene {

using Horizons = std::array<float, 8>;

// `tangents` from headTangents(head). `reach` in head units; 0 picks 4 eyeball radii
// (eyeSphere of eye_l, about 5 cm), or a fifth of the head's height without eyes.
std::vector<Horizons> skinHorizons(const HeadMesh& head,
                                   const std::vector<Eigen::Vector4f>& tangents, float reach = 0);

}  // namespace lacrima::scene
