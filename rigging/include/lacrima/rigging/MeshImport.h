#pragma once
// Bringing your own head: any mesh file assimp reads (OBJ + MTL, FBX, glTF/GLB, Collada, ...).
#include <lacrima/common/HeadMesh.h>

#include <string>

namespace lacrima::rigging {

// Runs assimp in this process: a damaged file can crash or hang it. The programs read a user's
// file with importHeadMeshIsolated (ImportProcess.h), which runs this in lacrima-import.
//
// Reads `path` into a HeadMesh, without changing its units or axes (the head must already be in
// the face frame: +y up, +x the face's own left, +z forward).
//
// Every mesh instance in the file's node graph becomes one sub-mesh, in depth-first node order
// (for an OBJ file: one per group and material, in file order), with the node's transform
// applied. Its name is its material's name, else the mesh's name, else "mesh"; a repeated name
// gets "_2", "_3", ... appended. Polygons are triangulated; points and lines are dropped.
//
// Vertices are those after assimp's aiProcess_JoinIdenticalVertices: face corners that agree
// in position, uv and normal become one vertex (assimp's OBJ reader alone gives every face
// corner its own vertex), numbered in order of first use by the mesh's faces. Vertex i of a
// sub-mesh is vertex i of that joined aiMesh, so a feature point stored as "vertex i of
// sub-mesh S" (see FeaturePointFile.h) stays valid for the same file: the numbering is
// deterministic for a given file and assimp version (Debian 12's assimp 5.2). Corners that
// differ in uv (seams) stay separate coincident copies, which HeadMesh::computeNormals and
// weldCoincidentVertices treat as one point.
//
// Uvs are the first channel, stored as (u, 1 - v); a mesh without uvs gets (0, 0), and the
// HeadMesh has no uvs when no mesh has any. Normals come from HeadMesh::computeNormals (the
// file's own normals are ignored so every head is lit the same way).
//
// Materials: one per material used, with diffuse colour (alpha = opacity), specular colour,
// shininess, and the diffuse texture resolved to an absolute path (relative paths against the
// file's folder). Embedded textures and texture files that do not exist are left out (plain
// colour). transparent is set when the opacity is below 1 or an opacity map is present.
//
// Throws FileError naming `path` and what was expected when it does not exist, is empty, when
// assimp cannot read it (with assimp's message), or when it holds nothing to rig: no faces
// (only vertices, points or lines; the message counts what it found) or only zero-area
// triangles.
HeadMesh importHeadMesh(const std::string& path);

}  // namespace lacrima::rigging
