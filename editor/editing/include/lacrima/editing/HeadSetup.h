#pragma once
// The Head workspace's document: an imported head, what each of its sub-meshes is for, and the
// feature points placed on it, with undo. No widgets: the workspace (editor/head) shows it, the
// tests drive it directly.
//
// A point is a spot on the surface (a vertex, or a triangle with barycentric weights, as in a
// feature-point file) and where it came from: placed (or moved) by hand, or proposed from the
// hand ones by rigging::proposeFeaturePoints. Every edit is one QUndoCommand on undoStack():
// set a role, place a point from a pick, move a point (snapped to its part's surface), remove a
// point, propose (replaces every proposed point at once and keeps the hand ones).
//
// The document maps to a lacrima-fdp v1 file (FeaturePointFile.h): roles become the
// "submeshes" lists (see HeadSetupRoles.h), proposed points carry "placed": "proposed" (hand is the
// default). Opening a file reads the roles back (unlisted parts keep their guess when it is an
// unlisted role, else become Rigid) and keeps what the editor does not edit (eye centres, neck
// pivot, tear sources, radii) so saving does not lose it.
#include <lacrima/common/HeadMesh.h>
#include <lacrima/editing/HeadSetupRoles.h>
#include <lacrima/rigging/FeaturePointFile.h>
#include <lacrima/rigging/ImportProcess.h>

#include <Eigen/Core>
#include <QObject>
#include <QString>
#include <QUndoStack>

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace lacrima::editing {

struct PlacedPoint {
  rigging::FeaturePointSpec spec;  // spec.placedByHand: placed or moved by hand
  bool byHand() const { return spec.placedByHand; }
};
using PlacedPoints = std::map<std::string, PlacedPoint, rigging::FdpIdLess>;

// A spot on the head: a triangle of a sub-mesh (local index) and barycentric weights of its
// corners, e.g. from the viewport's pick.
struct SurfaceSpot {
  int submesh = -1;
  int triangle = -1;
  Eigen::Vector3d barycentric = Eigen::Vector3d::Zero();
};

// What proposals carry onto the new head: a complete feature-point file on its mesh.
struct ProposalReference {
  HeadMesh mesh;
  rigging::FeaturePointFile file;
  // The default head with media/default-head.fdp.json. Throws FileError (not fetched yet:
  // rigging::defaultHeadFetchCommand()).
  static std::shared_ptr<const ProposalReference> loadDefault();
};

class HeadSetup : public QObject {
  Q_OBJECT
 public:
  explicit HeadSetup(QObject* parent = nullptr);
  ~HeadSetup() override;

  // --- the head -------------------------------------------------------------------------
  // Reads a mesh in the importer process (rigging::importHeadMeshIsolated: a file that crashes
  // or hangs assimp costs that process, not the editor). Throws rigging::ImportError naming the
  // file; options.cancelled stops it at once. Safe to call on any thread (it touches no
  // document).
  static HeadMesh importMesh(const QString& path, const rigging::ImportOptions& options = {});
  // Starts a new document on `mesh` (read from `path`): guessed roles, no points, empty undo
  // history. A mesh with no triangles is refused (std::invalid_argument) and nothing changes.
  void setMesh(const QString& path, HeadMesh mesh);
  // Import and setMesh in one. Throws, leaving the document as it was.
  void importFile(const QString& path);
  bool hasMesh() const { return mesh_ != nullptr; }
  // Precondition for mesh(): hasMesh(). The shared pointer lets a background job keep it.
  const HeadMesh& mesh() const { return *mesh_; }
  std::shared_ptr<const HeadMesh> sharedMesh() const { return mesh_; }
  QString meshPath() const { return meshPath_; }

  // --- roles ------------------------------------------------------------------------------
  const std::vector<PartRole>& roles() const { return roles_; }
  PartRole role(int submesh) const { return roles_.at(static_cast<std::size_t>(submesh)); }
  void setRole(int submesh, PartRole role);  // undoable; no-op when unchanged

  // --- points -----------------------------------------------------------------------------
  const PlacedPoints& points() const { return points_; }
  const PlacedPoint* point(const std::string& id) const;
  std::optional<Eigen::Vector3d> position(const std::string& id) const;
  // Places `id` by hand at `spot` (a corner within 1e-3 of weight 1 becomes that vertex).
  // A point that belongs on the skin (every one but the pupils 3.5/3.6, the teeth's 9.8-9.11
  // and the tongue's 6.x) picked on another part (the eyeball shows in front of the eye
  // corners, lashes over the lids) goes to the closest skin point instead. Throws
  // std::invalid_argument for a spot outside the mesh.
  void placePoint(const std::string& id, const SurfaceSpot& spot);
  // Moves `id` by hand to the closest point to `target` on the parts with the role of the
  // sub-mesh it is on (a skin point stays on the skin, an eye point on its eye). No-op for an
  // unknown id.
  void movePoint(const std::string& id, const Eigen::Vector3d& target);
  void removePoint(const std::string& id);
  // Whether the FDP table puts `id` on the skin (see placePoint).
  static bool belongsOnSkin(const std::string& id);
  // The closest spot to `target` on every sub-mesh whose role is `role`; nullopt when none has
  // triangles.
  std::optional<SurfaceSpot> snapToRole(const Eigen::Vector3d& target, PartRole role) const;

  // --- proposal ---------------------------------------------------------------------------
  // The hand points and the roles as a partial file (the proposal's input).
  rigging::FeaturePointFile handFile() const;
  // The proposal for `hand` on `mesh` (hand points kept, the rest carried from `reference`),
  // as points. Thread-safe (a pure function). Throws FileError naming missing anchors.
  static PlacedPoints computeProposal(const rigging::FeaturePointFile& hand, const HeadMesh& mesh,
                                      const ProposalReference& reference,
                                      Warnings* warnings = nullptr);
  // Replaces every proposed point by `proposal`'s proposed points (its hand points are
  // ignored: the document's own stay), as one undoable step.
  void applyProposal(const PlacedPoints& proposal);
  // computeProposal + applyProposal.
  void propose(const ProposalReference& reference, Warnings* warnings = nullptr);

  // --- files ------------------------------------------------------------------------------
  // The document as a feature-point file (path: fdpPath(), or the mesh path + ".fdp.json"),
  // every point with its position (recordPositions).
  rigging::FeaturePointFile toFile() const;
  // Saves toFile() atomically to `path`, which becomes fdpPath(); marks the history clean.
  // Throws FileError.
  void save(const QString& path);
  // Opens a feature-point file for the current mesh: validated (FeaturePointSet::Partial)
  // against it, so a file for another mesh is refused with its errors and nothing changes.
  // Clears the undo history. Throws FileError.
  void openFeaturePoints(const QString& path, Warnings* warnings = nullptr);
  QString fdpPath() const { return fdpPath_; }

  QUndoStack* undoStack() { return &undo_; }

  // --- used by the commands ---------------------------------------------------------------
  void assignRole(int submesh, PartRole role);
  void assignPoint(const std::string& id, const std::optional<PlacedPoint>& point);
  void assignPoints(PlacedPoints points);

 signals:
  void meshChanged();    // a new head (everything else changed too)
  void rolesChanged();   // one or more roles
  void pointsChanged();  // one or more points
  void changed();        // any of the above: what the rig depends on

 private:
  int submeshIndex(const std::string& name) const;

  std::shared_ptr<const HeadMesh> mesh_;
  QString meshPath_;
  QString fdpPath_;
  std::vector<PartRole> roles_;
  PlacedPoints points_;
  rigging::FeaturePointFile kept_;  // what an opened file had beyond roles and points
  QUndoStack undo_;
};

}  // namespace lacrima::editing
