#pragma once
// lacrima-player --export-gltf: an animation with its tears as one binary glTF 2.0 file that
// Blender, three.js and game engines play without plug-ins.
//
//  - The head at rest as the player shows it (every sub-mesh with its material and embedded
//    texture, GltfDocument.h), Y up, +Z forward, in metres (metresPerUnit, ExportOptions.h).
//  - One morph target per FAP pose of the rig, named by the FAP (mesh.extras.targetNames:
//    "open_jaw", "raise_b_midlip", ...); a target's weight is the FAP value / 1024.
//  - A skin of rigid joints: "body" (what does not follow the head), "head" at the neck pivot
//    (FAPs 48-50), "eye_left" and "eye_right" at the eyeballs' centres (23/25, 24/26); each vertex
//    follows one of them with weight 1.
//  - One animation, "lacrima", over the exported frames at the file's rate, sampled per frame
//    with LINEAR keys: the morph weights, and the joints' rotations when the file turns them
//    (slerp between frames, the player interpolates the angles; both agree at every frame).
//  - The tears: for every frame with tear geometry, a node "tears_NNNN" (under "tears") holding
//    that frame's water (the surface and the drops on the skin, a transmissive material with the
//    IOR of water) and wet trails (a tinted glossy film, COLOR_0's alpha its wetness). Its
//    scale is 0 at rest and keyed with STEP to 1 during its frame only, so exactly one frame's
//    tears show at a time.
// Redness, blush and the eyes' wetness (texture blending) are not carried: core glTF cannot
// animate a material, and the extension that can (KHR_animation_pointer) is read by neither
// Blender 3.4 nor three.js's loader.
#include <lacrima/export/ExportOptions.h>
#include <lacrima/playback/HeadRig.h>

#include <cstddef>

namespace lacrima::exporting {

struct GltfExportResult {
  int frames = 0;
  int morphTargets = 0;
  int tearFrames = 0;     // frames with a tears node
  std::size_t bytes = 0;  // of the .glb's binary chunk
  double metresPerUnit = 1;
  double seconds = 0;  // wall time
};

// Writes options.output atomically. Throws FileError for an unreadable input or an unwritable
// output (naming it), std::invalid_argument for a bad frame range, ExportCancelled when the
// progress callback asks to stop (nothing is written then).
GltfExportResult exportGltfAnimation(const playback::HeadRig& rig, const ExportOptions& options);

}  // namespace lacrima::exporting
