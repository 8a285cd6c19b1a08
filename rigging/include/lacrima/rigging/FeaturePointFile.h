#pragma once
// Feature-point files (*.fdp.json): where the MPEG-4 feature points sit on one particular head,
// plus what the rig needs besides them (which sub-meshes are skin, eyes, jaw; eye centres; the
// neck pivot; tear sources). Points are bound by index (a vertex, or a triangle and barycentric
// weights) and may carry their position beside it, so that a reader can tell when the vertex
// order changed (re-snap) or the file belongs to another mesh (refuse).
//
// Format, version 1 (UTF-8 JSON; unknown keys are warned about, never silently ignored):
//
//   {
//     "format": "lacrima-fdp",            required, exactly this
//     "version": 1,                       required; files of a later version are refused
//     "mesh": "free text",                optional: which head file this was placed on
//     "submeshes": {                      roles of the head's sub-meshes (names as loaded)
//       "skin": ["skin"],                 required, >= 1: the deforming surface; several
//                                         sub-meshes are joined where their vertices coincide
//       "eye_left": ["eye_l", "cornea_l"],   optional: turn rigidly with FAPs 23/25 (27, 29)
//       "eye_right": ["eye_r", "cornea_r"],  optional: FAPs 24/26 (28, 30)
//       "jaw": ["teeth_lower"],           optional: follow jaw point 2.1 rigidly (weight 1)
//       "tongue": ["tongue"],             optional: follow 2.1 rigidly; 6.x get own weights
//       "attached": ["eyelashes"],        optional: ride on the skin point closest to each vertex
//       "ignored": ["eye_occlusion"]      optional: not drawn, rigged or touched by tears (shading
//                                         shells and films another renderer needed)
//     },                                  other sub-meshes only follow the head rotation
//     "defaults": { "geodesics": "dijkstra" },   optional: "dijkstra" or "heat"
//     "points": {                         by FDP id "group.index"
//       "2.1": { "submesh": "skin", "vertex": 812, "position": [0.01, 5.93, 0.88] },
//       "2.2": { "submesh": "skin", "triangle": 97, "barycentric": [0.2, 0.3, 0.5] },
//       "4.3": { "submesh": "skin", "vertex": 17, "radius": 0.25, "geodesics": "heat" },
//       "8.3": { "submesh": "skin", "vertex": 420, "placed": "hand" }
//     },
//     "eyes": {                           optional; a missing centre is fitted (see below)
//       "left": { "centre": [0.308, 7.284, 1.236] }, "right": { ... }
//     },
//     "neck_pivot": [0, 6.2, -0.1],       feature point 7.1, in model units (inside the neck)
//     "tear_sources": {                   optional; surface points like "points" entries
//       "left": { "submesh": "skin", "vertex": 120 }, "right": { ... }
//     }
//   }
//
// A point is "vertex i of sub-mesh S" (global index S.firstVertex + i) or a point inside
// triangle t of S (local triangle index) with barycentric weights of its three corners, each in
// [0, 1] and summing to 1 within 1e-4. "radius" (model units, > 0) overrides the influence
// radius from InfluenceRadius.h; "geodesics" overrides the file's default method. "placed"
// ("hand" or "proposed", default "hand": a point somebody wrote into the file) records how the
// point came to be: placed by a person (in the editor's Head workspace or by hand), or carried
// over by proposeFeaturePoints (re-proposing replaces those and keeps the hand ones). The rig
// ignores it.
//
// "position" (optional, on points and tear sources): where the point was, in the mesh's own
// coordinates (before any face-frame rotation, FaceFrame.h), written by every Lacrima tool
// (recordPositions). validateFeaturePoints compares it with where the index now leads:
//  - within kPositionMatch x the mesh's bounding-box diagonal: the point is where the file says;
//  - else (the mesh was re-exported with its vertices in another order, or a vertex index is out
//    of range) the point is re-snapped to the nearest vertex of the same sub-mesh (a triangle
//    point: the closest surface point of that sub-mesh, as triangle + barycentric), with a
//    warning naming the file, line, column, JSON path, the point and how far it moved;
//  - when most positioned points have nothing of their sub-mesh within kPositionLost x ES0
//    (|3.5 - 3.6| from the stored positions; else kPositionLostDiagonal x the diagonal), or most
//    points name sub-meshes the head does not have or indices beyond its vertex counts, the file
//    is refused: "this feature-point file was placed on another mesh", naming the file, the
//    mesh and the first mismatches.
// A file without positions is bound by index alone: it stays valid and means what it says, but a
// file for another mesh whose indices happen to be in range cannot be told from a right one.
//
// Required points: the FAPU-defining ones (3.1-3.6, 9.15, 2.2, 8.3, 8.4); a missing one is an
// error. The other points moved by FAPs 3-68 are optional: a missing one is a named warning
// (its FAPs get no pose). Eye centres default to the least-squares sphere through the eye's
// vertices; a missing neck pivot defaults to the centre of the skin's lowest open boundary
// loop, with a warning. Tear sources default to the skin below 3.3 / 3.4 (see RigBuilder.h).
//
// Local indices of an imported mesh are those MeshImport.h produces (after assimp's
// JoinIdenticalVertices), deterministic for a given file and assimp version.
#include <lacrima/common/Diagnostics.h>
#include <lacrima/common/HeadMesh.h>
#include <lacrima/rigging/InfluenceWeights.h>

#include <Eigen/Core>

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lacrima::rigging {

inline constexpr int kFeaturePointFileVersion = 1;

// Orders FDP ids numerically by group, then index: "2.9" < "2.10" < "3.1".
struct FdpIdLess {
  bool operator()(std::string_view a, std::string_view b) const;
  using is_transparent = void;
};

struct SurfacePoint {
  std::string submesh;
  int vertex = -1;    // local vertex index, or -1 for a triangle point
  int triangle = -1;  // local triangle index, or -1 for a vertex point
  Eigen::Vector3d barycentric = Eigen::Vector3d::Zero();
  std::optional<Eigen::Vector3d> position;  // where it was, in mesh coordinates ("position")
};

// Position tolerances, as fractions (see the format above). kPositionMatch: the stored position
// is the shortest decimal that reads back as the float vertex exactly, so on the same mesh the
// difference is 0; 1e-5 of the diagonal (3 µm on a 30 cm head) still accepts a mesh re-exported
// through 32-bit floats or 6-digit OBJ text (errors about 1e-7 to 1e-6 of a coordinate) and is
// far below the shortest edge of a real head (the default head's: 5.6e-4 of its diagonal, the
// ICT head's 1.2e-4; test_rig_point_positions), so it never confuses two vertices. kPositionLost:
// 5% of the eye separation (about 3 mm on a real head) is more than a remeshed or slightly edited
// surface moves, and less than two different heads differ at a feature point.
inline constexpr double kPositionMatch = 1e-5;
inline constexpr double kPositionLost = 0.05;
inline constexpr double kPositionLostDiagonal = 0.01;

struct FeaturePointSpec {
  SurfacePoint at;
  std::optional<double> radius;
  std::optional<GeodesicMethod> geodesics;
  bool placedByHand = true;  // "placed": "hand" (the default) or "proposed"
};

struct EyeSpec {
  std::vector<std::string> submeshes;
  std::optional<Eigen::Vector3d> centre;
};

struct FeaturePointFile {
  std::string path;  // as given, for messages
  std::string text;  // as read, so that validateFeaturePoints can name lines and columns
  int version = kFeaturePointFileVersion;
  std::string meshNote;
  std::vector<std::string> skin, jaw, tongue, attached, ignored;
  EyeSpec eyeLeft, eyeRight;
  GeodesicMethod geodesics = GeodesicMethod::Dijkstra;
  std::map<std::string, FeaturePointSpec, FdpIdLess> points;
  std::optional<Eigen::Vector3d> neckPivot;
  std::optional<SurfacePoint> tearLeft, tearRight;
};

// The FDP ids that define the FAPUs (required in every file).
const std::vector<std::string>& fapuFeaturePoints();
// The FDP ids moved by FAPs 3-68 (each FAP's FapInfo::featurePoint), ascending.
const std::vector<std::string>& animatedFeaturePoints();

// Parses the file. Throws FileError listing every problem, each as "path:line:column: JSON
// path: what was expected", e.g. points."2.1".vertex. Unknown keys become warnings (located the
// same way) when `warnings` is given.
FeaturePointFile readFeaturePointFile(const std::string& path, Warnings* warnings = nullptr);

// Checks the file against `mesh` and returns it as the rig must use it: every named sub-mesh
// exists, indices are in range, barycentrics are valid, the required points exist and no
// sub-mesh has two roles; points with a "position" that the index no longer leads to are
// re-snapped (see the format above; the returned file has the new binding and its position).
// Throws FileError listing every error, each naming the line, column and JSON path of the
// feature point (or role) and what was expected, or, for a file that does not fit the mesh at
// all, "this feature-point file was placed on another mesh" with `meshName` (the mesh file, for
// the message; may be empty) and the first mismatches. Appends named warnings for re-snapped
// points and missing optional points. A file without positions comes back unchanged, so
// callers that only check may ignore the result.
// A Partial file (the input of proposeFeaturePoints, FeaturePointProposal.h) is checked the same
// way except that no point is required and missing ones are not warned about.
enum class FeaturePointSet { Complete, Partial };
FeaturePointFile validateFeaturePoints(const FeaturePointFile& file, const HeadMesh& mesh,
                                       Warnings* warnings,
                                       FeaturePointSet set = FeaturePointSet::Complete,
                                       std::string_view meshName = {});

// Sets every point's and tear source's "position" to where it is on `mesh` (validated), so a
// saved file can be checked against a re-exported mesh. Every file Lacrima writes has them.
void recordPositions(FeaturePointFile& file, const HeadMesh& mesh);

// The file as JSON text in the format above (points by id, in FdpIdLess order), for saving with
// saveAtomically; readFeaturePointFile reads it back to the same content.
std::string featurePointFileJson(const FeaturePointFile& file);

// Global vertex indices a point is bound to: one vertex, or the triangle's three corners.
// Precondition: the point was validated against `mesh`.
std::vector<int> surfaceVertices(const SurfacePoint& point, const HeadMesh& mesh);
// Takes the sub-meshes the file calls "ignored" out of the picture: their triangles are
// dropped (their vertices stay, so every index keeps its meaning), so nothing draws, picks,
// rigs or collides with them. Precondition: the file was validated against `mesh`.
void dropIgnoredParts(HeadMesh& mesh, const FeaturePointFile& file);
// Its position on the neutral mesh.
Eigen::Vector3d surfacePosition(const SurfacePoint& point, const HeadMesh& mesh);

std::string_view toString(GeodesicMethod method);

}  // namespace lacrima::rigging
