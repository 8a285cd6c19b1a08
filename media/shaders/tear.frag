#version 330 core
// The tear surface: water over skin. Output is premultiplied (blend one, one - alpha):
//   alpha  how much of the skin behind is hidden: none in the middle, where a drop just shows
//          the skin under it, growing towards the silhouette, where a real drop refracts the
//          dark surroundings and its optical path is longest; so a drop shows a dark rim and a
//          clear middle, as lenses of water do;
//   rgb    what the water adds: the studio reflected with a water fresnel (F0 = 0.02), sharp
//          glints of the three lights, and light focused through the drop onto its far side.
#include "common.glsl"

in vec3 vViewPos;
in vec3 vViewNormal;

out vec4 fragColour;

void main() {
  vec3 n = normalize(vViewNormal);
  vec3 v = normalize(-vViewPos);
  float nv = max(dot(n, v), 0.0);
  float fresnel = schlick(0.02, nv);
  float edge = 1.0 - nv;

  vec3 r = reflect(-v, n);
  vec3 light = studio(r) * fresnel * 1.5;
  light += studioSpecular(n, v, 700.0) * 0.30 + studioSpecular(n, v, 80.0) * 0.05;
  // Light focused by the drop onto the skin below it: a soft warm patch on the side away from
  // the key light.
  float caustic = pow(max(dot(n, normalize(v - kKeyDir * 0.7)), 0.0), 8.0);
  light += kKeyColour * vec3(1.0, 0.75, 0.62) * caustic * 0.035;

  float alpha = clamp(0.9 * edge * edge * edge, 0.0, 0.85);
  fragColour = vec4(displayIncrement(light), alpha);
}
