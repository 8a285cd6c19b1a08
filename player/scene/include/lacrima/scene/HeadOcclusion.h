#pragma once
// A static per-vertex occlusion in [0.25, 1] for the head's neutral shape: the cheap stand-in
// for ambient occlusion and contact shadows, which the renderer cannot afford per frame on a
// software rasteriser. Multiplies the lighting (head.vert passes it as uv1).
//
//   skin     creases and cavities: with L = (mean of the 1-ring) - p (the umbrella Laplacian
//            over welded vertices, so uv seams do not show) and e the mean ring edge length,
//            concavity c = max(0, L . n) / e, occlusion = clamp(1 - 1.3 c, 0.5, 1), then
//            smoothed by two rounds of 1-ring averaging: nostrils, lid folds, lip corners and
//            the eye sockets darken; convex parts keep 1.
//   eyes and corneas  1 near the front pole, down to 0.5 towards the socket,
//            mix(0.5, 1, smoothstep(0.3, 0.85, (p - c)/|p - c| . z)), and down to 0.45 where the
//            lids touch the eyeball: mix(0.45, 1, smoothstep(0.02 r, 0.35 r, g)), g the distance
//            to the nearest skin vertex (the lid's contact shadow); the smaller of the two.
//   teeth, tongue  darker towards the back of the mouth: mix(0.25, 0.85, smoothstep(0.2, 1, t)),
//            t the depth fraction over the mouth parts' z range.
//   anything else 1.
#include <lacrima/common/HeadMesh.h>

#include <vector>

namespace lacrima::scene {

std::vector<float> headOcclusion(const HeadMesh& head);

}  // namespace lacrima::scene
