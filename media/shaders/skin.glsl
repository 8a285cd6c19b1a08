// The skin's texture layers per pixel, shared by skin.frag (the face seen whole) and
// skin_detail.frag (close up, with the fine relief): the diffuse texture, the red
// irritated-skin layer (blended in by mask.r x redness: eyelids, under-eye, nose tip) and a
// blush tint (mask.g x blush: cheeks). The masks are painted in the head's uv space at start-up
// (OverlayMasks.h). The light comes per vertex (skin.vert). Written for a software rasteriser:
// the overlay layers are only fetched when and where they show, and a program without the
// relief (tilt a constant 0) does not even interpolate what it would need.

in vec2 vUv;
in vec3 vDiffuse;
in vec3 vRim;
in float vSheen;
in vec3 vKey;

uniform sampler2D diffuseMap;
uniform sampler2D maskMap;
uniform sampler2D rednessMap;
uniform vec4 overlay;         // x redness, y unused, z blush
uniform vec4 materialColour;

out vec4 fragColour;

// `tilt`: n'.l - n.l of the key light for the relief's normal n' (skin_detail.frag).
void shadeSkin(float tilt) {
  // Display-encoded texels throughout (see skin.vert): the layers blend in display space.
  vec3 texel = texture(diffuseMap, vUv).rgb * materialColour.rgb;
  float red = 0.0;
  if (overlay.x + overlay.z > 0.0) {  // uniform: a face without overlays fetches one texture
    vec2 mask = texture(maskMap, vUv).rg;
    red = mask.r * overlay.x;
    if (red > 0.0) texel = mix(texel, texture(rednessMap, vUv).rgb, red);
    texel *= mix(vec3(1.0), vec3(1.0, 0.77, 0.76), mask.g * overlay.z * 0.55);
  }
  // Rim and sheen add light: their display-space increments are small and nearly linear.
  // Irritated lids are moist: the redness makes the skin glossier too. The sheen's lobe is
  // narrower than the diffuse, so the relief moves it more.
  vec3 glow = vRim * texel * texel
            + kKeyColour * vSheen * (1.0 + 2.0 * red) * clamp(1.0 + 6.0 * tilt, 0.0, 2.0);
  fragColour = vec4(texel * vDiffuse * (1.0 + vKey.z * tilt) + displayIncrement(glow) * 0.8, 1.0);
}
