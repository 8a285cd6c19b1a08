#version 330 core
// Eyelashes and eyebrows: alpha-textured cards, lit softly from both sides (hair scatters).
#include "common.glsl"

in vec3 vViewPos;
in vec3 vViewNormal;
in vec2 vUv;
in float vOcclusion;

uniform sampler2D diffuseMap;
uniform vec4 materialColour;

out vec4 fragColour;

void main() {
  vec4 texel = texture(diffuseMap, vUv);
  float alpha = texel.a * materialColour.a;
  if (alpha < 0.02) discard;
  // Two-sided cards: face the normal towards the viewer. (gl_FrontFacing is no use here: OGRE
  // flips render-texture images vertically, which swaps what GL calls the front face.)
  vec3 n = normalize(vViewNormal);
  n = faceforward(n, vViewPos, n);
  vec3 albedo = toLinear(texel.rgb) * materialColour.rgb;
  vec3 light = hemisphere(n) + kKeyColour * (abs(dot(n, kKeyDir)) * 0.5 + 0.25)
             + kFillColour * abs(dot(n, kFillDir));
  fragColour = vec4(toDisplay(albedo * light * vOcclusion), alpha);
}
