#version 330 core
// Eyeball (sclera and iris) with its bloodshot layer (OverlayTextures.h): the layer's colour is
// the sclera at full redness (pink, vessels), its alpha the sclera weight, 0 on the iris and the
// pupil, so however red the eye gets the iris keeps the texture's own colour. The layer follows
// the eye redness (overlay.x, which lingers after crying) or, if higher, the tears at this eye
// (overlay.y); a wet or irritated sclera is glossier too. The clear cornea in front of the iris
// is drawn separately (cornea.frag).
#include "common.glsl"

in vec3 vViewPos;
in vec3 vViewNormal;
in vec2 vUv;
in float vOcclusion;

uniform sampler2D diffuseMap;
uniform sampler2D wetMap;
uniform vec4 overlay;  // x redness, y wetness of this eye
uniform vec4 materialColour;

out vec4 fragColour;

void main() {
  vec3 n = normalize(vViewNormal);
  vec3 v = normalize(-vViewPos);
  vec3 albedo = toLinear(texture(diffuseMap, vUv).rgb) * materialColour.rgb;
  float wet = overlay.y;
  float shine = 0.0;
  if (overlay.x + overlay.y > 0.0) {  // uniform: a calm eye fetches one texture
    vec4 layer = texture(wetMap, vUv);
    albedo = mix(albedo, toLinear(layer.rgb), max(overlay.x, overlay.y) * layer.a);
    shine = max(wet, 0.5 * overlay.x) * layer.a;
  }
  // Sclera is never paper white under a lid: keep it a little grey.
  albedo *= 0.82;

  float ao = vOcclusion;
  vec3 light = hemisphere(n) + kKeyColour * max(dot(n, kKeyDir) * 0.8 + 0.2, 0.0)
             + kFillColour * max(dot(n, kFillDir), 0.0);
  vec3 colour = albedo * light * ao;
  float fresnel = schlick(0.03, max(dot(n, v), 0.0));
  colour += studioSpecular(n, v, 90.0) * (0.02 + 0.06 * shine) * ao * ao;
  colour += studio(reflect(-v, n)) * fresnel * (0.4 + 0.8 * shine) * ao * ao;
  fragColour = vec4(toDisplay(colour), 1.0);
}
