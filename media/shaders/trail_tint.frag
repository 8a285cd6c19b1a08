#version 330 core
// Wet trails, first pass: multiplies the skin under the water (blend dest_colour zero). Wet
// skin scatters less light back and looks darker and more saturated; a rivulet's water also
// absorbs and refracts some of it. The tint keeps red and loses more blue, as wet skin does.
#include "trail.glsl"

out vec4 fragColour;

void main() {
  TrailFilm f = trailFilm();
  float amount = f.body * mix(0.35, 1.0, f.rivulet);
  vec3 wetSkin = vec3(0.91, 0.85, 0.83);
  fragColour = vec4(mix(vec3(1.0), wetSkin, amount), 1.0);
}
