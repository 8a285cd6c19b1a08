#pragma once
// Writes a baked rig as an OGRE 1.12 .mesh with pose animation, plus its .material script and
// texture copies, for the player (or any OGRE 1.12 application) to load.
//
// The .mesh holds:
//  - shared geometry for all vertices: positions alone in buffer 0 (pose animation rewrites
//    only that buffer, so it must not share it), normals and uvs (if any) in buffer 1;
//  - one sub-mesh per HeadSubmesh, in order and named like it, using the shared geometry, with
//    16-bit indices where its largest index is below 65535 (0xFFFF is the primitive-restart
//    index on GL) and 32-bit ones otherwise, and material "<prefix>/<material name>" (or
//    BaseWhite, which OGRE defines once a render system is up, for a sub-mesh without one);
//  - one pose per exported FAP (see RigExport.h), named "fapNN_name" (e.g. "fap03_open_jaw"),
//    target 0 (the shared geometry), whose offsets are the PoseSet offsets for a value of
//    kExportedPoseValue = 1024 (one X0 of the FAPU): the OGRE pose weight for FAP value v is
//    v / 1024, e.g. 0.5 for an open_jaw of 512;
//  - a manual animation "fap" of length 0 with one VAT_POSE track on the shared geometry and a
//    key frame at time 0 that references every pose with influence 0. To show FAP values set
//    keyFrame->updatePoseReference(i, v_i / 1024) and mark the entity's animation state dirty;
//  - bounds that contain the head with every FAP anywhere in options.boundsRangeFactor times
//    its slider range, and eyes and head turned in any direction, so OGRE never culls a face
//    that is actually on screen. Head/eye rotations are not poses and are not in the file.
//
// Beside it, "<stem>.material" (stem: the .mesh file name without extension) has one material
// per HeadMaterial, and each distinct diffuse texture is copied next to the .mesh under its
// own file name, which the script uses; so the folder is one self-contained OGRE resource
// location. Load the .mesh into the group that holds the script: OGRE resolves a sub-mesh's
// material in the mesh's own resource group.
//
// All files are written completely to temporaries first and then renamed over their targets,
// so a failure leaves the folder as it was. Bad input and failed reads or writes throw
// FileError naming the offending path and the reason.
//
// OGRE: uses the application's Root if there is one, else a private HeadlessOgre (no window,
// no render system, no log file). Not thread-safe: OGRE's managers are process-wide.
#include <lacrima/common/HeadMesh.h>
#include <lacrima/common/PoseSet.h>

#include <string>

namespace lacrima::exporters {

struct OgreExportOptions {
  // Material names become "<materialPrefix>/<HeadMaterial::name>"; empty means the .mesh file
  // name without extension, so two heads loaded into one resource group do not clash.
  std::string materialPrefix;
  // Bounds cover every FAP at up to this multiple of its editing slider range: FAP files may
  // exceed the practical range a little, and a too-large box only costs culling precision.
  float boundsRangeFactor = 2.0f;
  // Whether to write "<stem>.material" and copy the textures (false: the .mesh alone, e.g. when
  // the application supplies its own materials under the same names).
  bool writeMaterials = true;
};

void exportOgreMesh(const HeadMesh& head, const PoseSet& poses, const std::string& meshPath,
                    const OgreExportOptions& options = {});

}  // namespace lacrima::exporters
