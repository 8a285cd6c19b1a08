#pragma once
// Per-vertex tangent frames of a head's uv layout, for normal maps in texture space (the skin's
// detail relief, SkinDetail.h): xyz the unit tangent along +u (texture columns), orthogonal to
// the vertex normal; w = +1 or -1, the handedness: the direction of +v (texture rows, down) is
// w * cross(normal, tangent). Summed over each vertex's triangles (Lengyel's method, weighted by
// area) and not welded across uv seams, where the layout itself changes. A vertex on no
// triangle with a usable uv gradient, or a head without uvs, gets any unit tangent orthogonal to
// its normal and w = 1 (a flat detail map then shades nothing differently).
#include <lacrima/common/HeadMesh.h>

#include <Eigen/Core>

#include <vector>

namespace lacrima::scene {

std::vector<Eigen::Vector4f> headTangents(const HeadMesh& head);

}  // namespace lacrima::scene
