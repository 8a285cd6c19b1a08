#version 330 core
// Wet trails, second pass: what the water adds over the tinted skin (additive, premultiplied
// with zero alpha): sharp glints of the studio's lights along the rivulet and the lights'
// soft boxes mirrored with water's fresnel (F0 = 0.02), fading with the film.
#include "common.glsl"
#include "trail.glsl"

out vec4 fragColour;

void main() {
  TrailFilm f = trailFilm();
  vec3 v = normalize(-vViewPos);
  float fresnel = schlick(0.02, max(dot(f.normal, v), 0.0));
  vec3 r = reflect(-v, f.normal);
  vec3 light = studioSpecular(f.normal, v, mix(200.0, 1200.0, f.rivulet)) * mix(0.12, 0.5, f.rivulet)
             + studioLights(r) * (0.01 + 0.4 * fresnel) * mix(0.6, 1.0, f.rivulet);
  fragColour = vec4(displayIncrement(light) * f.body, 0.0);
}
