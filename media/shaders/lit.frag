#version 330 core
// Every other head part (teeth, tongue, parts of imported heads): the material's texture and
// colour, Lambert plus Blinn-Phong with the material's own specular.
#include "common.glsl"

in vec3 vViewPos;
in vec3 vViewNormal;
in vec2 vUv;
in float vOcclusion;

uniform sampler2D diffuseMap;
uniform vec4 materialColour;
uniform vec4 specularColour;  // rgb, w shininess

out vec4 fragColour;

void main() {
  vec3 n = normalize(vViewNormal);
  vec3 v = normalize(-vViewPos);
  vec3 albedo = toLinear(texture(diffuseMap, vUv).rgb) * materialColour.rgb;
  vec3 light = hemisphere(n) + kKeyColour * max(dot(n, kKeyDir), 0.0)
             + kFillColour * max(dot(n, kFillDir), 0.0);
  vec3 colour = albedo * light + specularColour.rgb * studioSpecular(n, v, max(specularColour.w, 1.0)) * 0.5;
  fragColour = vec4(toDisplay(colour * vOcclusion), 1.0);
}
