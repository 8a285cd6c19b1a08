#pragma once
// The skin's fine relief, which a 512 x 512 texture for a whole body cannot hold (the default
// head's face gets about 5 texels per centimetre): a tiling tangent-space normal map painted at
// start-up, repeated many times over the skin's uv space (skin.frag), so close-ups show pores
// and fine lines instead of a smooth blur. Engine-free: QImage out (Format_RGBA8888, RGB = the
// normal x 0.5 + 0.5 with +x along the rows, +y down the columns (texture v), +z out of the
// skin; alpha 255).
//
// Height field on the torus (it tiles in both directions), in units of the tile's texels:
//   pores   one per cell of a 16 x 16 grid, jittered inside its cell: a round dip, Gaussian of
//           radius 0.10 to 0.18 cells, depth 0.5 to 1
//   lines   shallow grooves where value noise (6 and 11 cells across) crosses 0.5: the closed,
//           wandering furrows between the plateaus of skin
//   grain   value noise, 64 cells across, a little
// normal = normalize(-kSlope dh/dx, -kSlope dh/dy, 1) by central differences. Every term is
// periodic, so the map averages to a flat normal: over any whole tile it neither darkens nor
// tilts the light.
#include <lacrima/common/HeadMesh.h>

#include <QImage>

namespace lacrima::scene {

QImage makeSkinDetailNormals(int size = 256);

// How many times the relief repeats per uv unit on this head's skin so that one tile spans
// about 1.5 cm: 1.25 eyeball radii (eyeSphere of eye_l, an eyeball being about 12 mm in radius),
// or a sixteenth of the head's height without eyes, over the skin's median uv length per unit
// of length (the default head: about 66). 64 for a head without skin or uvs.
float skinDetailTiling(const HeadMesh& head);

// How strongly the relief shades the skin with the camera at `distance` from its target, given
// the distance that frames the whole face (OrbitView::framing): 1 from half that distance
// inwards, 0 from three quarters outwards, smooth between. Farther out a tile spans too few
// pixels for pores to show (at 1280x720 in the framing view, about 33 pixels, a pore every
// 2), while fetching the relief costs a fifth of the frame on llvmpipe, so the framing views
// keep their old cost and the close-ups, where the texture alone is a blur, get the relief.
float skinDetailStrength(double distance, double framingDistance);

}  // namespace lacrima::scene
