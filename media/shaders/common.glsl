// Shared by every Lacrima fragment shader (pasted in where a shader says #include "common.glsl").
//
// Lighting is a studio rig fixed to the camera, so the face stays well lit from any orbit angle:
// directions are in view space (camera looks along -z, +y up, +x right). Shading happens in
// linear light: textures are decoded with gamma 2.2, the result goes through a filmic curve
// (Narkowicz's fit of ACES) and is encoded again.
//   key   warm, from the upper left in front: shapes the face
//   fill  cool and dim, from the right: lifts the shadow side
//   rim   from behind and above: separates the head from the background
//   sky / ground hemisphere ambient
// Normals are never flipped by gl_FrontFacing: OGRE renders into textures upside down and
// swaps the winding to match, so gl_FrontFacing means opposite things on screen and off screen.
// studio() is the same rig seen as an environment (soft boxes on a dark gradient). Wet
// surfaces reflect it, which is what makes tears read as water.

const vec3 kKeyDir = vec3(-0.4924, 0.5416, 0.6812);   // normalize(-0.5, 0.55, 0.69)
const vec3 kKeyColour = vec3(1.00, 0.92, 0.82) * 1.55;
const vec3 kFillDir = vec3(0.7399, 0.0740, 0.6688);   // normalize(0.75, 0.075, 0.678)
const vec3 kFillColour = vec3(0.72, 0.76, 0.86) * 0.40;
const vec3 kRimDir = vec3(0.4447, 0.5337, -0.7196);   // normalize(0.45, 0.54, -0.728)
const vec3 kRimColour = vec3(0.90, 0.95, 1.00) * 1.3;
const vec3 kSky = vec3(0.11, 0.12, 0.14);
const vec3 kGround = vec3(0.05, 0.045, 0.04);

vec3 toLinear(vec3 c) { return c * c; }

vec3 toDisplay(vec3 c) {
  c *= 0.85;  // exposure
  vec3 mapped = (c * (2.51 * c + 0.03)) / (c * (2.43 * c + 0.59) + 0.14);
  return sqrt(clamp(mapped, 0.0, 1.0));
}

// Light added over what is already in the (display-encoded) frame buffer, as with additive or
// premultiplied blending. Encoding the increment alone (pow 1/2.2) would make faint light far
// too bright; near mid-grey the encoding's slope is about 1, and the exponential keeps strong
// glints from clipping harshly.
vec3 displayIncrement(vec3 linear) { return 1.0 - exp(-1.1 * linear); }

vec3 hemisphere(vec3 n) { return mix(kGround, kSky, n.y * 0.5 + 0.5); }

float schlick(float f0, float cosTheta) {
  float m = 1.0 - clamp(cosTheta, 0.0, 1.0);
  float m2 = m * m;
  return f0 + (1.0 - f0) * m2 * m2 * m;
}

// Normalised Blinn-Phong lobe: the peak grows with the exponent, so a tighter lobe stays as
// bright in total and highlights on water look like sharp glints, not faint dots.
float blinn(vec3 n, vec3 l, vec3 v, float shininess) {
  vec3 h = normalize(l + v);
  return pow(max(dot(n, h), 0.0), shininess) * (shininess + 8.0) / 25.1327;
}

float softBox(vec3 r, vec3 centre, float cosOuter, float cosInner) {
  return smoothstep(cosOuter, cosInner, dot(r, centre));
}

// The three lights seen as soft boxes along direction r (view space).
vec3 studioLights(vec3 r) {
  return kKeyColour * 2.0 * softBox(r, kKeyDir, 0.90, 0.97)
       + kFillColour * 1.5 * softBox(r, kFillDir, 0.85, 0.95)
       + kRimColour * 1.2 * softBox(r, kRimDir, 0.92, 0.98);
}

// Radiance seen along direction r (view space): a dark studio with the three lights as soft boxes.
vec3 studio(vec3 r) {
  return mix(vec3(0.035, 0.035, 0.04), vec3(0.16, 0.165, 0.18), r.y * 0.5 + 0.5) + studioLights(r);
}

// Key, fill and rim specular for a lobe of the given exponent.
vec3 studioSpecular(vec3 n, vec3 v, float shininess) {
  return kKeyColour * blinn(n, kKeyDir, v, shininess) * max(dot(n, kKeyDir), 0.0)
       + kFillColour * blinn(n, kFillDir, v, shininess) * max(dot(n, kFillDir), 0.0)
       + kRimColour * blinn(n, kRimDir, v, shininess) * max(dot(n, kRimDir), 0.0);
}
