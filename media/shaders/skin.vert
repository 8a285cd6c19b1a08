#version 330 core
// Skin lighting, per vertex: the default head's skin has 4,500 vertices and covers 200,000
// pixels at 1280x720. Diffuse light varies slowly across a face and the skin's sheen is a broad
// lobe, so interpolating them costs nothing visible, while on a software rasteriser every
// per-pixel operation and every interpolated value counts (skin.frag keeps only the texture
// layers and the fine relief, which needs just the key light in the tangent frame from here).
// The skin's own shadows from the key light come per vertex too, from horizons computed once
// (SkinHorizons.h), so they follow the camera-fixed light at no per-pixel cost.
#include "common.glsl"

in vec4 vertex;
in vec3 normal;
in vec2 uv0;
in float uv1;
in vec4 uv2;  // tangent along +u (head frame) and handedness (HeadTangents.h)
in vec4 uv3;  // horizons, sectors 0-3 (SkinHorizons.h)
in vec4 uv4;  // horizons, sectors 4-7

uniform mat4 worldViewProj;
uniform mat4 worldView;

out vec2 vUv;
out vec3 vDiffuse;  // the light, tone-mapped and display-encoded: multiplies the texel
out vec3 vRim;      // rim glow, display-encoded, before the albedo tints it
out float vSheen;   // key-light sheen (linear; the redness makes it stronger)
out vec3 vKey;      // xy: the key light's direction in the tangent plane; z: how much a tilt
                    // of the normal by the detail relief changes vDiffuse, relative to it

// Under the jaw, the nose and the chin the skin faces the neck and the chest, which the key
// light falls on: warm light bounces back up (head frame, so the chest stays below the head
// whatever the camera does). Without it, and without the jaw's shadow on the neck
// (keyVisibility), the jaw's underside was the only unlit skin between the lit cheek and the
// lit neck, lit by the dark ground ambient and the cool fill alone: a grey crease.
const vec3 kBounce = vec3(0.56, 0.40, 0.32);
// Skin's shadows are warm: light scattered under the skin from the lit side carries red
// furthest, so this much of the key reaches into a cast shadow.
const vec3 kShadowLeak = vec3(0.32, 0.12, 0.06);

// How much of the key light reaches this vertex past the skin around it: the light's elevation
// (sine) against the horizon interpolated between the two sectors either side of its azimuth,
// with a soft edge (vertices are about a centimetre apart). A vertex with no horizon in that
// direction is never shadowed, however low the light: the wrap still lights it past the
// terminator, as light scattered under the skin does.
float keyVisibility(vec3 keyTangent) {
  float horizons[8] = float[8](uv3.x, uv3.y, uv3.z, uv3.w, uv4.x, uv4.y, uv4.z, uv4.w);
  float sector = mod(atan(keyTangent.y, keyTangent.x) / 0.785398 + 8.0, 8.0);
  int below = int(sector) % 8;
  float horizon = mix(horizons[below], horizons[(below + 1) % 8], fract(sector));
  return mix(1.0, smoothstep(horizon - 0.2, horizon + 0.05, keyTangent.z),
             smoothstep(0.0, 0.15, horizon));
}

vec3 wrapDiffuse(float nl) {
  // Light wraps past the terminator, more so in red, as light scattered under the skin does.
  const vec3 wrap = vec3(0.42, 0.20, 0.14);
  return clamp((nl + wrap) / ((1.0 + wrap) * (1.0 + wrap)), 0.0, 1.0);
}

void main() {
  vec3 position = (worldView * vertex).xyz;
  vec3 n = normalize(mat3(worldView) * normal);
  vec3 v = normalize(-position);
  vec3 tangent = mat3(worldView) * uv2.xyz;
  tangent = normalize(tangent - n * dot(n, tangent));  // the pose bends the normal, not the uv
  vec3 bitangent = uv2.w * cross(n, tangent);
  vUv = uv0;
  float ao = uv1;
  float keyNl = dot(n, kKeyDir);
  vec3 keyTangent = vec3(dot(kKeyDir, tangent), dot(kKeyDir, bitangent), keyNl);
  float visible = keyVisibility(keyTangent);
  float key = visible * (0.5 + 0.5 * ao);
  vec3 keyShade = mix(kShadowLeak, vec3(1.0), visible) * (0.5 + 0.5 * ao);
  float down = max(-normalize(normal).y, 0.0);  // squared below: undersides, not every cheek
  vec3 diffuse = hemisphere(n) * ao + kKeyColour * wrapDiffuse(keyNl) * keyShade
               + kFillColour * wrapDiffuse(dot(n, kFillDir)) * ao
               + kBounce * down * down * ao;
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
  float lobe = pow(max(dot(n, normalize(kKeyDir + v)), 0.0), 24.0) * max(keyNl, 0.0);
  float sheen = lobe * (0.09 + 1.2 * schlick(0.028, nv)) * key;
  vRim = kRimColour * rim;
  vSheen = sheen;

  // The detail relief tilts the normal a little: to first order n.l changes by the relief's
  // (x, y) dotted with the key's tangent-plane direction. The key's diffuse changes by
  // d(wrap)/d(n.l) = 1 / 1.44 (green) per unit of n.l inside the wrap, and the display encoding
  // (about a square root) halves the relative change; capped where the light is so dim that the
  // relative change would run away.
  float slope = (keyNl > -0.2 && keyNl < 1.24 ? kKeyColour.g / 1.44 : 0.0) * key;
  vKey = vec3(keyTangent.xy, min(0.5 * slope / max(diffuse.g, 0.05), 1.5));
  gl_Position = worldViewProj * vertex;
}
