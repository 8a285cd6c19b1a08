#pragma once
// A rigged head ready to animate: the mesh, its rig (poses, FAPU, tear sources) and the blender.
// Built in memory at start-up (about 25 ms for the default head), so the player and editor work
// with any head the rigging layer accepts, not only pre-exported ones.
#include <lacrima/common/HeadMesh.h>
#include <lacrima/common/PoseSet.h>
#include <lacrima/rigging/FaceFrame.h>
#include <lacrima/rigging/RigBuilder.h>

#include <Eigen/Core>

#include <memory>
#include <string>
#include <vector>

namespace lacrima::playback {

struct HeadRig {
  HeadMesh head;
  rigging::BuiltRig rig;  // rig.input.mesh points at `head`: a HeadRig is never copied or moved
  std::unique_ptr<PoseBlender> blender;
  // The axis rotation that brought the head as imported into the face frame (FaceFrame.h):
  // head and rig are in the face frame; imported coordinates = frame.rotation^T x head's.
  rigging::FaceFrame frame;
  // Feature-point file and rig warnings ("file: message"), for a status line or stderr.
  std::vector<std::string> warnings;

  HeadRig() = default;
  HeadRig(const HeadRig&) = delete;
  HeadRig& operator=(const HeadRig&) = delete;
};

// The default head (fetched at set-up) with media/default-head.fdp.json. Throws FileError
// naming what is missing when the head has not been fetched (packaging/fetch-default-head.sh).
std::unique_ptr<HeadRig> loadDefaultHeadRig();
// Any mesh assimp reads, read in the importer process (ImportProcess.h), with its feature-point
// file (lacrima-fdp v1). Throws FileError. A progress callback that throws stops the import too.
// `options.progress` reports the whole load: reading the mesh, the feature points, the rig.
std::unique_ptr<HeadRig> loadHeadRig(const std::string& meshPath, const std::string& fdpPath,
                                     const rigging::RigOptions& options = {});
// A head already in memory with its feature points (the editor's Head workspace rigs what the
// user placed without writing files): validates `fdp` against `head` (messages name fdp.path;
// points whose stored position moved are re-snapped with a warning), brings head and points
// into the face frame (bringToFaceFrame: any export axes play upright), builds the rig and the
// blender. The one path from a mesh and its feature points to a rig: loadHeadRig and
// loadDefaultHeadRig go through it too. Throws FileError; `options.progress` reports the stages.
std::unique_ptr<HeadRig> rigHead(HeadMesh head, const rigging::FeaturePointFile& fdp,
                                 const rigging::RigOptions& options = {});

// The triangles of every sub-mesh the feature-point file calls skin (rig.roles), by head vertex
// index: the surface tears run on. For the default head, exactly its "skin" sub-mesh.
std::vector<Eigen::Vector3i> skinTriangles(const HeadRig& rig);
// The triangles of the eye sub-meshes (roles eye_left and eye_right: eyeballs and corneas), by
// head vertex index. With the skin they make the tears' collision surface: they close the skin's
// eye openings, so a tear that reaches the lid margin runs over the eye instead of into the head.
std::vector<Eigen::Vector3i> eyeTriangles(const HeadRig& rig);

}  // namespace lacrima::playback
