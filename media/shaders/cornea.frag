#version 330 core
// The clear front of the eye, added over the iris: only reflections and glints show, which is
// what makes an eye look alive. A wet eye (overlay.y) reflects more and glints harder.
#include "common.glsl"

in vec3 vViewPos;
in vec3 vViewNormal;
in vec2 vUv;
in float vOcclusion;

uniform vec4 overlay;

out vec4 fragColour;

void main() {
  vec3 n = normalize(vViewNormal);
  vec3 v = normalize(-vViewPos);
  float wet = overlay.y;
  float fresnel = schlick(0.04, max(dot(n, v), 0.0));
  vec3 colour = studio(reflect(-v, n)) * fresnel * (0.8 + 0.8 * wet);
  colour += studioSpecular(n, v, 600.0) * (0.08 + 0.10 * wet);
  colour *= vOcclusion;
  fragColour = vec4(displayIncrement(colour), 0.0);
}
