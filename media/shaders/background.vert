#version 330 core
// The backdrop: a grid of vertices already in clip space (identity view and projection), each
// carrying its colour (uv0), so the gradient and vignette cost nothing per pixel.
in vec4 vertex;
in vec3 uv0;
uniform mat4 worldViewProj;
out vec3 vColour;
void main() {
  vColour = uv0;
  gl_Position = worldViewProj * vertex;
}
