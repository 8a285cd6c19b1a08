#version 330 core
// The tear surface: water over skin. Output is premultiplied (blend one, one - alpha):
//   alpha  how much of the skin behind is hidden: a little everywhere (water over skin
//          refracts and absorbs some of it, which reads as the skin darkening under the drop),
//          more towards the silhouette, where the optical path is longest; kept low, so a small
//          drop does not show a dark ring;
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
  light += studioSpecular(n, v, 900.0) * 0.55 + studioSpecular(n, v, 90.0) * 0.06;
  // Light focused by the drop onto the skin below it: a soft warm patch on the side away from
  // the key light.
  float caustic = pow(max(dot(n, normalize(v - kKeyDir * 0.7)), 0.0), 8.0);
  light += kKeyColour * vec3(1.0, 0.75, 0.62) * caustic * 0.05;

  float alpha = clamp(0.06 + 0.22 * edge * edge, 0.0, 0.4);
  fragColour = vec4(displayIncrement(light), alpha);
}
