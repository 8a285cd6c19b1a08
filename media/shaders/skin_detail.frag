#version 330 core
// Skin close up: its texture layers (skin.glsl) and a tiling relief of pores and fine lines
// (SkinDetail.h) that shades the key light's diffuse and breaks up its sheen.
#include "common.glsl"
#include "skin.glsl"

uniform sampler2D detailMap;
uniform float detailTiling;  // relief tiles per uv unit (about 1.5 cm each)
uniform vec4 detail;         // x: the relief's strength (skinDetailStrength)

void main() {
  // n'.l - n.l to first order for the relief's normal n' (its x, y in the tangent frame): no
  // bias where the mipmaps average the relief flat, so the light keeps its level.
  shadeSkin(detail.x * dot(texture(detailMap, vUv * detailTiling).xy * 2.0 - 1.0, vKey.xy));
}
