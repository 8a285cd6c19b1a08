#version 330 core
// A sphere impostor: discard outside the disc, reconstruct the sphere's normal and depth so
// spheres intersect the skin and each other correctly.
#include "common.glsl"

in vec2 vCorner;
in vec3 vCentre;

uniform mat4 projection;
uniform vec4 sphere;

out vec4 fragColour;

void main() {
  float r2 = dot(vCorner, vCorner);
  if (r2 > 1.0) discard;
  vec3 n = vec3(vCorner, sqrt(1.0 - r2));
  vec3 p = vCentre + n * sphere.x;
  vec4 clip = projection * vec4(p, 1.0);
  gl_FragDepth = clip.z / clip.w * 0.5 + 0.5;
  vec3 v = normalize(-p);
  vec3 albedo = vec3(0.10, 0.35, 0.85);
  vec3 colour = albedo * (hemisphere(n) + kKeyColour * max(dot(n, kKeyDir), 0.0)
                          + kFillColour * max(dot(n, kFillDir), 0.0));
  colour += studioSpecular(n, v, 120.0) * 0.15;
  fragColour = vec4(toDisplay(colour), 1.0);
}
