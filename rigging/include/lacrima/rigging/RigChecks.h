#pragma once
// Rig checks: what a user should look at before trusting a rigged head, each with its figures.
// Run on a built rig (buildRig) and its feature-point file; nothing is changed.
//
//  - "wrong-part" (Error): a feature point on a sub-mesh of the wrong role. The FDP table puts
//    the pupils 3.5 / 3.6 on the left / right eye, 6.x on the tongue, 9.8 / 9.10 on the upper
//    teeth (no role: rigid, they stay with the skull) and 9.9 / 9.11 on the lower teeth ("jaw",
//    or rigid where the teeth are one sub-mesh), every other point on the skin. 7.1 (the neck
//    pivot) is not a surface point.
//  - "asymmetry" (Warning): a left point mirrored across the mid-sagittal plane lands farther
//    than options.asymmetryTolerance * ES0 from its right twin (3.7 <-> 3.12, 3.11 <-> 3.8,
//    8.3 <-> 8.4, ...). The plane is the least-squares plane through the midline points
//    present (2.1, 2.2, 2.3, 2.10, 8.1, 8.2, 9.3, 9.8-9.12, 9.15, 11.1, 11.4-11.6): centroid c
//    and normal n = the eigenvector of their scatter matrix with the smallest eigenvalue,
//    turned towards the face's own left (the mean of left - right over the twins). When the
//    midline points are fewer than three, (nearly) collinear, or give a normal more than 60
//    degrees from the left - right direction, n is that mean direction and c the mean of the
//    twins' midpoints. Mirror: p' = p - 2 ((p - c).n) n.
//  - "zero-fapu" (Error): an X0 that is (nearly) zero, so the FAPs counting in it barely move:
//    ES0 below kNearZeroFapuOfSkinSize of the skin's bounding-box diagonal, or IRISD0, ENS0,
//    MNS0 or MW0 below kNearZeroFapuOfEs of ES0 (closed eyes give IRISD0 ~ 0).
//  - "lips-joined" (Error): opening the jaw (FAP 3 at kLipsCheckOpenJaw MNS units) moves the
//    chin 2.1 by d; the inner-lip gap between 2.2 and 2.3 (and between 2.6 / 2.8 and 2.7 / 2.9,
//    along the mouth, when present) must grow by at least kLipsMinOpening * d, else the lips
//    are joined: they share vertices, or the upper lip follows the jaw. The points' positions
//    under the pose are their bound vertices' neutral positions plus the pose's offsets,
//    blended with the binding's weights.
//  - "pose-moves-nothing" (Warning): a FAP 3-68 whose feature point exists but whose pose, at
//    the end of its slider range farthest from 0, moves no vertex by more than
//    kPoseMovesNothingOfEs * ES0 (translations: |offset| * value; eye and head rotations: the
//    chord 2 r sin(angle / 2) of the vertex farthest from the centre; the eye FAPs of a head
//    that lacks them is "no-eyes" instead).
//  - "no-eyes" (Warning): the rig has no usable left (right) eye, so FAPs 23, 25, 27, 29 (24,
//    26, 28, 30) and the tears 69 (70) are disabled (BuiltRig::disabledFaps); its pupil point
//    is then not held to the eye by "wrong-part".
#include <lacrima/common/HeadMesh.h>
#include <lacrima/rigging/FeaturePointFile.h>
#include <lacrima/rigging/RigBuilder.h>

#include <string>
#include <vector>

namespace lacrima::rigging {

struct RigCheck {
  enum class Severity { Warning, Error };
  Severity severity = Severity::Warning;
  std::string kind;                 // "wrong-part", "asymmetry", "zero-fapu",
                                    // "lips-joined", "pose-moves-nothing", "no-eyes"
  std::vector<std::string> points;  // FDP ids concerned (may be empty)
  int fap = 0;                      // FAP number concerned, 0 = none
  std::string message;              // one sentence for the user, with the figures
};

struct RigCheckOptions {
  double asymmetryTolerance = 0.05;  // ES0
};

// The thresholds of the checks above (fractions of the named distance).
inline constexpr double kNearZeroFapuOfSkinSize = 0.01;
inline constexpr double kNearZeroFapuOfEs = 0.02;
inline constexpr double kLipsCheckOpenJaw = 512.0;  // FAP 3 value, MNS units (0.5 MNS0)
inline constexpr double kLipsMinOpening = 0.05;
inline constexpr double kPoseMovesNothingOfEs = 1e-3;

// The checks that fire, in the order of the list above (within a kind, by FDP id or FAP).
// `rig` must have been built from `mesh` and `fdp`.
std::vector<RigCheck> checkRig(const HeadMesh& mesh, const FeaturePointFile& fdp,
                               const BuiltRig& rig, const RigCheckOptions& options = {});

// "error: lips-joined (2.2, 2.3; FAP 3): ..." - one line for a log or a terminal.
std::string toString(const RigCheck& check);

}  // namespace lacrima::rigging
