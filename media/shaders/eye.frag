#version 330 core
// Eyeball (sclera and iris) with a wet overlay layer: a bloodshot, watery version of the eye
// texture blended in by overlay.y (the eye's wetness), which also makes the eye glossier. The
// clear cornea in front of the iris is drawn separately (cornea.frag).
#include "common.glsl"

in vec3 vViewPos;
in vec3 vViewNormal;
in vec2 vUv;
in float vOcclusion;

uniform sampler2D diffuseMap;
uniform sampler2D wetMap;
uniform vec4 overlay;  // y wetness of this eye
uniform vec4 materialColour;

out vec4 fragColour;

void main() {
  vec3 n = normalize(vViewNormal);
  vec3 v = normalize(-vViewPos);
  float wet = overlay.y;
  vec3 albedo = toLinear(texture(diffuseMap, vUv).rgb) * materialColour.rgb;
  albedo = mix(albedo, toLinear(texture(wetMap, vUv).rgb), wet * 0.85);
  // Sclera is never paper white under a lid: keep it a little grey.
  albedo *= 0.82;

  float ao = vOcclusion;
  vec3 light = hemisphere(n) + kKeyColour * max(dot(n, kKeyDir) * 0.8 + 0.2, 0.0)
             + kFillColour * max(dot(n, kFillDir), 0.0);
  vec3 colour = albedo * light * ao;
  float fresnel = schlick(0.03, max(dot(n, v), 0.0));
  colour += studioSpecular(n, v, 90.0) * (0.02 + 0.06 * wet) * ao * ao;
  colour += studio(reflect(-v, n)) * fresnel * (0.4 + 0.8 * wet) * ao * ao;
  fragColour = vec4(toDisplay(colour), 1.0);
}
