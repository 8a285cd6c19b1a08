#pragma once
// Writes a baked rig as a binary glTF 2.0 file (.glb) with morph targets, for tools outside
// OGRE (Blender, three.js, model viewers).
//
// The file holds one node with one mesh, and:
//  - one primitive per HeadSubmesh that has triangles (glTF has no empty primitives), in
//    order, each a window on the shared vertex arrays: POSITION, NORMAL and, when the head has
//    uvs, TEXCOORD_0. HeadMesh uvs are OGRE-style: converted from OBJ/three.js by v' = 1 - v,
//    so (0, 0) is the upper left corner of the image and v grows downwards. That already is
//    glTF's convention (glTF 2.0 spec, "Images": "The origin of the UV coordinates (0, 0)
//    corresponds to the upper left corner of a texture image"), so TEXCOORD_0 = HeadMesh uvs,
//    not flipped; a flip would turn every texture upside down in glTF viewers. (Importers with
//    a lower-left origin, e.g. assimp, flip v themselves when they read glTF.)
//    Indices are local to the primitive, 16-bit up to 65535 vertices, else 32-bit;
//  - one material per HeadMaterial: pbrMetallicRoughness with baseColorFactor = diffuse,
//    baseColorTexture = the diffuse texture embedded as PNG (other image formats are converted),
//    metallic 0, roughness from the Blinn-Phong shininess s as roughness = (2 / (s + 2))^(1/4)
//    (the usual match of s to GGX alpha = roughness^2), alphaMode BLEND for transparent
//    materials, colours with alpha < 1 and the cornea (which is also made glossy);
//  - one morph target per exported FAP pose (see RigExport.h), in channel order, with POSITION
//    deltas for a value of kExportedPoseValue = 1024, so a target weight is FAP value / 1024.
//    glTF needs the same targets on every primitive: a primitive a pose does not touch gets an
//    all-zero target. Target names "fapNN_name" (e.g. "fap03_open_jaw") are in
//    mesh.extras.targetNames (the convention Blender and three.js read), mesh.weights are all 0;
//  - accessor min/max for every POSITION, as the spec requires.
// Vertices that belong to no primitive are not written. Rotations (eyes, head) are not
// exported: glTF morph targets are linear.
//
// The file is written atomically. Bad input and failed reads or writes throw FileError naming
// the offending path and the reason.
#include <lacrima/common/HeadMesh.h>
#include <lacrima/common/PoseSet.h>

#include <string>

namespace lacrima::exporters {

void exportGlb(const HeadMesh& head, const PoseSet& poses, const std::string& path);

}  // namespace lacrima::exporters
