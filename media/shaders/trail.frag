#version 330 core
// Wet trails: a thin water film on the skin. It darkens the skin a little (wet skin scatters
// less light back) and mirrors the studio and its lights, all scaled by the trail's wetness and
// by the film's thickness across the trail (full in the middle, none at the edges), so a
// drying trail fades out and no trail shows a hard border. Premultiplied output.
#include "common.glsl"

in vec3 vViewPos;
in vec3 vViewNormal;
in float vWetness;
in float vAcross;

out vec4 fragColour;

void main() {
  // The film is thickest along the middle (the trail mesh raises it): tilt the skin's normal
  // towards the facet's own, so the sheen rounds across the trail like a bead of water.
  vec3 facet = normalize(cross(dFdx(vViewPos), dFdy(vViewPos)));
  vec3 n = normalize(vViewNormal);
  facet = faceforward(facet, vViewPos, facet);
  n = normalize(mix(n, facet, 0.12));
  vec3 v = normalize(-vViewPos);
  float across = clamp(abs(vAcross), 0.0, 1.0);
  float wet = clamp(vWetness, 0.0, 1.0) * (1.0 - across * across);
  float fresnel = schlick(0.02, max(dot(n, v), 0.0));
  // Only the lights are worth reflecting: the dark studio around them would just grey the skin.
  vec3 light = studioSpecular(n, v, 300.0) * 0.12 + studioLights(reflect(-v, n)) * (0.02 + 1.5 * fresnel);
  fragColour = vec4(displayIncrement(light) * wet, 0.06 * wet);
}
