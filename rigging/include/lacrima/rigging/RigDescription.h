#pragma once
// rig.json: what the player needs to know about a rig besides the .mesh, and what --report
// prints. Both are JSON with fields in a fixed, documented order (JsonWriter).
//
// rig.json, version 1 (lengths in the head's own model units; every position in the face frame,
// FaceFrame.h: +x the face's left, +y up, +z forward, whatever axes the head was exported with):
//   format "lacrima-rig", version 1, mesh (the .mesh file name), glb,
//   face_frame { axes, rotation [[r00,r01,r02],[..],[..]], measured, tilt_degrees }
//                                                   the axis rotation applied to the imported
//                                                   mesh (face frame = rotation x mesh; identity
//                                                   for a Y-up head facing +z), whether it was
//                                                   measured from the feature points, and the
//                                                   face's remaining turn in the model
//   fapu { IRISD0, ES0, ENS0, MNS0, MW0 }          the neutral distances X0 (unit = X0 / 1024)
//   feature_points { "2.1": { position [x,y,z], radius, geodesics }, ... }   radius/geodesics
//                                                   only for points with a falloff influence
//   eyes { left: { centre, vertices }, right: ... }  rotation centres of FAPs 23-26
//   neck_pivot [x,y,z]                               feature point 7.1, for FAPs 48-50
//   tear_sources { left: { vertex, position, normal }, right: ... }   skin vertex (global index)
//                                                   under each lower lid where tears well up
//   submeshes [ { name, role, first_vertex, vertex_count } ]   roles: skin, eye_left, eye_right,
//                                                   jaw, tongue, attached, rigid
//   poses [3, 4, ...]                                FAPs with a pose or rotation group
//   disabled_faps [23, 25, ...]                      FAPs the head cannot play (no usable eye:
//                                                    its turns and its tears; rig.md, Bad heads)
//   warnings [ "..." ]
#include <lacrima/rigging/FaceFrame.h>
#include <lacrima/rigging/RigBuilder.h>

#include <string>

namespace lacrima::rigging {

struct RigFiles {
  std::string ogreMesh = "head.mesh";
  std::string glb = "head.glb";
};

// `mesh` and `rig` are in the face frame (bringToFaceFrame ran before buildRig); `frame` says
// which rotation brought them there.
std::string rigDescriptionJson(const HeadMesh& mesh, const BuiltRig& rig,
                               const RigFiles& files = {}, const FaceFrame& frame = {});

// The --report text: FAPU values and, for each translational FAP 3-68, its feature point,
// pose size (vertices), X0, the displacement of the point for a value of 1024 computed by
// blending the baked pose (so it checks the whole chain), their ratio, and warnings:
//   "no pose", "displacement differs from X0 by more than 0.1%", "moves the point off the FAP's
//   axis" (a sideways component above 0.1% of X0).
std::string rigReportJson(const HeadMesh& mesh, const BuiltRig& rig);

// The displacement of feature point `id` (its bound vertices, barycentric mix for triangle
// points) by the linear pose of `fap` at `value`; zero when the pose or point is missing.
Eigen::Vector3d featurePointDisplacement(const BuiltRig& rig, const std::string& id, int fap,
                                         double value);

}  // namespace lacrima::rigging
