#version 330 core
// Skin lighting, per vertex: the default head's skin has 4,500 vertices and covers 200,000
// pixels at 1280x720. Diffuse light varies slowly across a face and the skin's sheen is a broad
// lobe, so interpolating them costs nothing visible, while on a software rasteriser every
// per-pixel operation and every interpolated value counts (skin.frag keeps only the texture
// layers).
#include "common.glsl"

in vec4 vertex;
in vec3 normal;
in vec2 uv0;
in float uv1;

uniform mat4 worldViewProj;
uniform mat4 worldView;

out vec2 vUv;
out vec3 vDiffuse;  // the light, tone-mapped and display-encoded: multiplies the texel
out vec3 vRim;      // rim glow, display-encoded, before the albedo tints it
out float vSheen;   // key-light sheen (linear; the redness makes it stronger)

vec3 wrapDiffuse(float nl) {
  // Light wraps past the terminator, more so in red, as light scattered under the skin does.
  const vec3 wrap = vec3(0.42, 0.20, 0.14);
  return clamp((nl + wrap) / ((1.0 + wrap) * (1.0 + wrap)), 0.0, 1.0);
}

void main() {
  vec3 position = (worldView * vertex).xyz;
  vec3 n = normalize(mat3(worldView) * normal);
  vec3 v = normalize(-position);
  vUv = uv0;
  float ao = uv1;
  vec3 diffuse = hemisphere(n) * ao + kKeyColour * wrapDiffuse(dot(n, kKeyDir)) * (0.5 + 0.5 * ao)
               + kFillColour * wrapDiffuse(dot(n, kFillDir)) * ao;
  // Texels are display-encoded (gamma 2): display(albedo x light) = texel x display(light)
  // exactly without the filmic curve. With it, the product is exact for a reference albedo
  // (0.5, typical skin) and close for others, since the curve bends slowly:
  //   vDiffuse = display(0.5 light) / sqrt(0.5).
  // So the whole tone mapping runs per vertex, not per pixel.
  vDiffuse = toDisplay(diffuse * 0.5) * 1.41421;
  float nv = max(dot(n, v), 0.0);
  float edge = 1.0 - nv;
  // Only near the silhouette (a high power of 1 - n.v): internal contours such as the jaw line
  // would otherwise catch a rim light the jaw really shadows.
  float edge2 = edge * edge;
  float rim = edge2 * edge2 * clamp(dot(n, kRimDir) + 0.2, 0.0, 1.0) * ao;
  // One Blinn-Phong lobe of the key light under a Schlick fresnel.
  float lobe = pow(max(dot(n, normalize(kKeyDir + v)), 0.0), 24.0) * max(dot(n, kKeyDir), 0.0);
  float sheen = lobe * (0.09 + 1.2 * schlick(0.028, nv)) * ao;
  vRim = kRimColour * rim;
  vSheen = sheen;
  gl_Position = worldViewProj * vertex;
}
