#version 330 core
// Tear surface and wet trails: view-space position and normal. Trails also carry uv0, their
// wetness (1 wet .. 0 dry) and where the vertex lies across the trail (-1 left edge, 0 middle,
// 1 right edge), and the direction across the trail from its left edge to its right (tangent);
// the tear surface has neither (GL then reads zeros).
in vec4 vertex;
in vec3 normal;
in vec2 uv0;
in vec3 tangent;

uniform mat4 worldViewProj;
uniform mat4 worldView;

out vec3 vViewPos;
out vec3 vViewNormal;
out vec3 vViewAcross;
out float vWetness;
out float vAcross;

void main() {
  vViewPos = (worldView * vertex).xyz;
  vViewNormal = mat3(worldView) * normal;
  vViewAcross = mat3(worldView) * tangent;
  vWetness = uv0.x;
  vAcross = uv0.y;
  gl_Position = worldViewProj * vertex;
}
