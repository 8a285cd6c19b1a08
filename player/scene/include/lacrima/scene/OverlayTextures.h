#pragma once
// The overlay layers themselves, made from the head's own textures at start-up (so they match
// whatever skin and eyes a head brings). Engine-free: QImage in, QImage out (Format_RGBA8888).
//
// Irritated skin (the redness layer): in linear light, each texel becomes
//   (0.92 r, 0.56 g m, 0.66 b m),  m = 0.82 .. 1.12 from two octaves of value noise
// (about 20 and 60 blotches across the texture): redder (towards pink, not orange) and darker,
// mottled as skin flushed by crying is, not a flat tint. The mask decides where it shows
// (OverlayMasks.h).
//
// Bloodshot eye (the eye's redness layer): its alpha is the sclera weight, 1 on bright, nearly
// grey texels (in linear light, saturation below 0.18 and brightest channel above 0.27, fading
// out by saturation 0.3 and brightness 0.12), 0 on the iris and the pupil; its colour, where the
// alpha is not 0, is the sclera at full redness: pink (green and blue x 0.64, 0.66), a little
// brighter (a film of water scatters light), with red vessels: long winding lines where warped
// value noise crosses 0.5 and finer twigs between. Texels with alpha 0 keep their colour bit for
// bit, so eye.frag, which blends the layer in by alpha x redness, never changes an iris,
// whatever its colour (a grey iris would count as sclera: the rule is by colour). The eye
// shader adds the gloss.
//
// Island padding (for the skin's own texture too): texels a sub-mesh's uv triangles cover are
// found by rasterising them; the outermost covered ring is dropped (island borders are often
// painted badly, and bilinear filtering at a uv seam blends them in, which shows as a thin line
// along the seam, e.g. where the default head's face island meets the neck); then covered
// colours are grown outwards `grow` texels (each uncovered texel takes the mean of its covered
// neighbours, ring by ring). Texels farther out keep their colour.
#include <lacrima/common/HeadMesh.h>

#include <QImage>

namespace lacrima::scene {

QImage makeIrritatedSkin(const QImage& skinDiffuse);
QImage makeWetEye(const QImage& eyeDiffuse);
QImage padUvIslands(const QImage& texture, const HeadMesh& head, const HeadSubmesh& submesh,
                    int grow = 4);

}  // namespace lacrima::scene
