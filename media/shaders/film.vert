#version 330 core
// Tear surface and wet trails: view-space position and normal; uv0 is the trail's wetness
// (1 wet .. 0 dry) and where the vertex lies across the trail (-1 left edge, 0 middle, 1 right
// edge); the tear surface has no uv0.
in vec4 vertex;
in vec3 normal;
in vec2 uv0;

uniform mat4 worldViewProj;
uniform mat4 worldView;

out vec3 vViewPos;
out vec3 vViewNormal;
out float vWetness;
out float vAcross;

void main() {
  vViewPos = (worldView * vertex).xyz;
  vViewNormal = mat3(worldView) * normal;
  vWetness = uv0.x;
  vAcross = uv0.y;
  gl_Position = worldViewProj * vertex;
}
