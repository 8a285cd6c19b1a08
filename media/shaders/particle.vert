#version 330 core
// Particle spheres as camera-facing impostors: four vertices per particle share its centre
// (vertex) and differ in their corner (uv0, -1..1); the quad is expanded in view space here.
in vec4 vertex;
in vec2 uv0;

uniform mat4 worldView;
uniform mat4 projection;
uniform vec4 sphere;  // x radius (head units)

out vec2 vCorner;
out vec3 vCentre;

void main() {
  vec4 centre = worldView * vertex;
  vCorner = uv0;
  vCentre = centre.xyz;
  gl_Position = projection * (centre + vec4(uv0 * sphere.x, 0.0, 0.0));
}
