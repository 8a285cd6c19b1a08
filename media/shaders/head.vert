#version 330 core
// Every head sub-mesh: positions and normals come deformed from the CPU (PoseBlender) each
// frame; uv1 carries a static per-vertex occlusion (HeadOcclusion.h).
in vec4 vertex;
in vec3 normal;
in vec2 uv0;
in float uv1;

uniform mat4 worldViewProj;
uniform mat4 worldView;

out vec3 vViewPos;
out vec3 vViewNormal;
out vec2 vUv;
out float vOcclusion;

void main() {
  vViewPos = (worldView * vertex).xyz;
  vViewNormal = mat3(worldView) * normal;  // the head is never scaled non-uniformly
  vUv = uv0;
  vOcclusion = uv1;
  gl_Position = worldViewProj * vertex;
}
