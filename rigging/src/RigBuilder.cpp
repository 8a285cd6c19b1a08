#include <lacrima/rigging/RigBuilder.h>

#include "SkinAttachment.h"

#include <lacrima/common/FapTable.h>
#include <lacrima/rigging/InfluenceRadius.h>
#include <lacrima/rigging/SkinTopology.h>
#include <lacrima/rigging/SphereFit.h>
#include <lacrima/rigging/SurfaceGraph.h>

#include <algorithm>
#include <limits>
#include <memory>
#include <set>
#include <stdexcept>

namespace lacrima::rigging {
namespace {

// The vertices of the named sub-meshes (a name the mesh lacks contributes none: validation
// reports it, and an eye made only of missing sub-meshes is then an absent eye).
std::vector<int> verticesOf(const HeadMesh& mesh, const std::vector<std::string>& names) {
  std::vector<int> out;
  for (const std::string& name : names) {
    const HeadSubmesh* s = mesh.findSubmesh(name);
    if (!s) continue;
    for (int v = 0; v < s->vertexCount; ++v) out.push_back(s->firstVertex + v);
  }
  return out;
}

bool contains(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

// Nearest vertex of `candidates` to each of `queries`, by a uniform grid over the candidates
// (cell ~ mean spacing), searched in growing shells until the best hit is certain.
class NearestVertex {
 public:
  NearestVertex(const Eigen::Matrix3Xf& positions, std::vector<int> candidates)
      : positions_(positions), candidates_(std::move(candidates)) {
    lo_ = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
    Eigen::Vector3d hi = -lo_;
    for (int v : candidates_) {
      lo_ = lo_.cwiseMin(positions_.col(v).cast<double>());
      hi = hi.cwiseMax(positions_.col(v).cast<double>());
    }
    const double volume = std::max((hi - lo_).prod(), 1e-30);
    cell_ = std::max(
        std::cbrt(volume / std::max<double>(1.0, static_cast<double>(candidates_.size()))), 1e-9);
    dims_ = ((hi - lo_) / cell_).array().floor().cast<int>() + 1;
    cells_.resize(static_cast<std::size_t>(dims_.prod()));
    for (int v : candidates_)
      cells_[static_cast<std::size_t>(flat(cellOf(positions_.col(v).cast<double>())))].push_back(v);
  }

  int nearest(const Eigen::Vector3d& p) const {
    const Eigen::Vector3i c = cellOf(p);
    int best = -1;
    double bestD2 = std::numeric_limits<double>::infinity();
    for (int ring = 0; ring <= dims_.maxCoeff(); ++ring) {
      for (int x = c.x() - ring; x <= c.x() + ring; ++x)
        for (int y = c.y() - ring; y <= c.y() + ring; ++y)
          for (int z = c.z() - ring; z <= c.z() + ring; ++z) {
            if (std::max({std::abs(x - c.x()), std::abs(y - c.y()), std::abs(z - c.z())}) != ring)
              continue;
            if (x < 0 || y < 0 || z < 0 || x >= dims_.x() || y >= dims_.y() || z >= dims_.z())
              continue;
            for (int v : cells_[static_cast<std::size_t>(flat({x, y, z}))]) {
              const double d2 = (positions_.col(v).cast<double>() - p).squaredNorm();
              if (d2 < bestD2) bestD2 = d2, best = v;
            }
          }
      // Everything outside this shell is at least `ring * cell` away.
      if (best >= 0 && std::sqrt(bestD2) <= ring * cell_) break;
    }
    return best;
  }

 private:
  Eigen::Vector3i cellOf(const Eigen::Vector3d& p) const {
    Eigen::Vector3i c = ((p - lo_) / cell_).array().floor().cast<int>();
    return c.cwiseMax(0).cwiseMin(dims_ - Eigen::Vector3i::Ones());
  }
  int flat(const Eigen::Vector3i& c) const {
    return (c.z() * dims_.y() + c.y()) * dims_.x() + c.x();
  }

  const Eigen::Matrix3Xf& positions_;
  std::vector<int> candidates_;
  Eigen::Vector3d lo_;
  double cell_ = 1;
  Eigen::Vector3i dims_;
  std::vector<std::vector<int>> cells_;
};

// Adds `extra` (vertex, weight) pairs to an influence, keeping the larger weight per vertex
// and vertices ascending.
void merge(FeaturePointInfluence& influence, const std::vector<std::pair<int, float>>& extra) {
  std::map<int, float> all;
  for (std::size_t k = 0; k < influence.vertices.size(); ++k)
    all[influence.vertices[k]] = influence.weights[k];
  for (const auto& [v, w] : extra) {
    float& slot = all[v];
    slot = std::max(slot, w);
  }
  influence.vertices.clear();
  influence.weights.clear();
  for (const auto& [v, w] : all) {
    influence.vertices.push_back(v);
    influence.weights.push_back(w);
  }
}

// An eye's rotation group, or an empty group and the reason when the head has no usable eye on
// that side (no eye_<side> role, its sub-meshes missing or empty, or no centre to turn about).
RotationGroup eyeGroup(const HeadMesh& mesh, const EyeSpec& spec, const std::string& side,
                       std::optional<Eigen::Vector3d>& centre, std::optional<double>& radius,
                       std::string& absent) {
  RotationGroup group;
  if (spec.submeshes.empty()) {
    absent = "no sub-mesh has the role eye_" + side;
    return group;
  }
  group.vertices = verticesOf(mesh, spec.submeshes);
  if (group.vertices.empty()) {
    absent = "the sub-meshes of submeshes.eye_" + side + " are missing or have no vertices";
    return group;
  }
  if (spec.centre) {
    centre = *spec.centre;
  } else {
    Eigen::Matrix3Xd points(3, static_cast<Eigen::Index>(group.vertices.size()));
    for (std::size_t k = 0; k < group.vertices.size(); ++k)
      points.col(static_cast<Eigen::Index>(k)) =
          mesh.positions.col(group.vertices[k]).cast<double>();
    const auto sphere = fitSphere(points);
    if (!sphere) {
      absent = "eyes." + side + ".centre is not given and the " + side +
               " eye's vertices do not span a sphere to fit one to (give it)";
      group.vertices.clear();
      return group;
    }
    centre = sphere->centre;
    radius = sphere->radius;
  }
  group.centre = centre->cast<float>();
  return group;
}

// What a missing eye disables: its turns, thrust and pupil, and its tears. Tears need the eye:
// its sub-meshes close the skin's eye opening in the tears' collision surface (a drop at the lid
// margin would otherwise fall into the head), and the eye is what weeps.
void disableEye(BuiltRig& rig, const std::string& side, const std::string& why) {
  const bool left = side == "left";
  const std::vector<int> faps = left ? std::vector<int>{23, 25, 27, 29, kTearLeftFap}
                                     : std::vector<int>{24, 26, 28, 30, kTearRightFap};
  rig.disabledFaps.insert(rig.disabledFaps.end(), faps.begin(), faps.end());
  std::sort(rig.disabledFaps.begin(), rig.disabledFaps.end());
  rig.warnings.push_back("no " + side + " eye (" + why + "): FAPs " + std::to_string(faps[0]) +
                         ", " + std::to_string(faps[1]) + ", " + std::to_string(faps[2]) + " and " +
                         std::to_string(faps[3]) +
                         " (eyeball turns, thrust, pupil) are disabled; no eyes: tears " +
                         "need the eye's sub-meshes to close the skin's eye opening, so the " +
                         side + " tears (FAP " + std::to_string(faps[4]) + ") are disabled too");
}

// Skin points whose influence stops at the edge of their piece of a multi-piece skin (separate
// lip or ear pieces that are not welded): the skin vertices within half the point's radius, in
// a straight line, that lie on another piece (stray vertices on no triangle are no piece).
// Geodesics cannot cross the gap, so those vertices do not follow the point; the warning names how
// many and where.
void warnUnreachedPieces(const HeadMesh& mesh, const SurfaceGraph& skin, const std::string& id,
                         const std::vector<int>& sources, const Eigen::Vector3d& at, double radius,
                         std::vector<std::string>& warnings) {
  if (skin.componentCount < 2 || sources.empty()) return;
  const int own = skin.component[static_cast<std::size_t>(
      skin.nodeOfVertex[static_cast<std::size_t>(sources.front())])];
  int unreached = 0;
  std::set<std::string> where;
  for (int n = 0; n < skin.nodeCount(); ++n) {
    if (skin.component[static_cast<std::size_t>(n)] == own) continue;
    const auto k = static_cast<std::size_t>(n);
    if (skin.firstNeighbour[k] == skin.firstNeighbour[k + 1]) continue;  // a stray vertex
    if ((skin.positions.col(n) - at).norm() >= 0.5 * radius) continue;
    ++unreached;
    where.insert(mesh.submeshes[static_cast<std::size_t>(mesh.submeshOfVertex(
                                    skin.vertexOfNode[static_cast<std::size_t>(n)]))]
                     .name);
  }
  if (unreached == 0) return;
  std::string names;
  for (const std::string& name : where) names += (names.empty() ? "\"" : ", \"") + name + "\"";
  warnings.push_back("feature point " + id + ": its influence cannot reach " +
                     std::to_string(unreached) + " skin vertices within half its radius (" +
                     std::to_string(0.5 * radius) + ") that lie on another piece of the skin (" +
                     names +
                     "), not joined to its own; they will not follow it (weld the pieces, " +
                     "or give them another role)");
}

TearSource tearSourceAt(const HeadMesh& mesh, int vertex) {
  TearSource t;
  t.vertex = vertex;
  t.position = mesh.positions.col(vertex).cast<double>();
  if (mesh.normals.cols() == mesh.positions.cols())
    t.normal = mesh.normals.col(vertex).cast<double>().normalized();
  return t;
}

}  // namespace

BuiltRig buildRig(const HeadMesh& mesh, const FeaturePointFile& fdp, const RigOptions& options) {
  auto progress = [&](double f, std::string_view stage) {
    if (options.progress) options.progress(f, stage);
  };
  BuiltRig rig;
  const std::string& path = fdp.path;

  progress(0.0, "feature points");
  for (const auto& [id, spec] : fdp.points) {
    rig.featurePoints[id] = surfacePosition(spec.at, mesh);
    const std::vector<int> bound = surfaceVertices(spec.at, mesh);
    auto& binding = rig.bindings[id];
    for (std::size_t k = 0; k < bound.size(); ++k)
      binding.emplace_back(
          bound[k], bound.size() == 1 ? 1.0 : spec.at.barycentric[static_cast<Eigen::Index>(k)]);
  }
  const auto& fp = rig.featurePoints;
  FapuReferencePoints ref{fp.at("3.1"), fp.at("3.2"),  fp.at("3.3"), fp.at("3.4"), fp.at("3.5"),
                          fp.at("3.6"), fp.at("9.15"), fp.at("2.2"), fp.at("8.3"), fp.at("8.4")};
  try {
    rig.fapu = computeFapu(ref);
  } catch (const std::invalid_argument& e) {
    throw FileError({path, 0, 0}, std::string("FAPU: ") + e.what());
  }

  for (const auto& name : fdp.skin) rig.roles[name] = "skin";
  for (const auto& name : fdp.eyeLeft.submeshes) rig.roles[name] = "eye_left";
  for (const auto& name : fdp.eyeRight.submeshes) rig.roles[name] = "eye_right";
  for (const auto& name : fdp.jaw) rig.roles[name] = "jaw";
  for (const auto& name : fdp.tongue) rig.roles[name] = "tongue";
  for (const auto& name : fdp.attached) rig.roles[name] = "attached";
  for (const auto& name : fdp.ignored) rig.roles[name] = "ignored";
  for (const HeadSubmesh& s : mesh.submeshes) rig.roles.emplace(s.name, "rigid");

  RigInput& in = rig.input;
  in.mesh = &mesh;
  in.fapu = rig.fapu;
  for (const auto& [id, p] : fp) in.featurePoints[id] = p.cast<float>();
  std::string noLeftEye, noRightEye;
  in.eyeLeft = eyeGroup(mesh, fdp.eyeLeft, "left", rig.eyeCentreLeft, rig.eyeRadiusLeft, noLeftEye);
  in.eyeRight =
      eyeGroup(mesh, fdp.eyeRight, "right", rig.eyeCentreRight, rig.eyeRadiusRight, noRightEye);
  if (!noLeftEye.empty()) disableEye(rig, "left", noLeftEye);
  if (!noRightEye.empty()) disableEye(rig, "right", noRightEye);

  progress(0.05, "surface graphs");
  const SurfaceGraph skinGraph = buildSurfaceGraph(mesh, fdp.skin);
  const GeodesicMethod fileMethod = options.geodesics.value_or(fdp.geodesics);
  bool needHeat = fileMethod == GeodesicMethod::Heat, needDijkstra = !needHeat;
  for (const auto& [id, spec] : fdp.points) {
    const GeodesicMethod m = spec.geodesics.value_or(fileMethod);
    needHeat = needHeat || m == GeodesicMethod::Heat;
    needDijkstra = needDijkstra || m == GeodesicMethod::Dijkstra;
  }
  // Heat factors the whole skin once; build only the solvers the points ask for.
  progress(0.1, needHeat ? "factoring the heat method" : "surface graphs");
  std::unique_ptr<InfluenceWeights> skinDijkstra, skinHeat, tongueWeights;
  if (needDijkstra)
    skinDijkstra = std::make_unique<InfluenceWeights>(skinGraph, GeodesicMethod::Dijkstra);
  if (needHeat) skinHeat = std::make_unique<InfluenceWeights>(skinGraph, GeodesicMethod::Heat);
  if (!fdp.tongue.empty())
    tongueWeights = std::make_unique<InfluenceWeights>(buildSurfaceGraph(mesh, fdp.tongue),
                                                       GeodesicMethod::Dijkstra);

  const std::vector<int> attached = verticesOf(mesh, fdp.attached);
  const SkinAttachment attachment = attachToSkin(mesh, fdp.skin, attached);

  const std::size_t total = fdp.points.size();
  std::size_t done = 0;
  for (const auto& [id, spec] : fdp.points) {
    progress(0.15 + 0.7 * static_cast<double>(done++) /
                        static_cast<double>(std::max<std::size_t>(total, 1)),
             "influence of " + id);
    const std::string& sub = spec.at.submesh;
    const std::vector<int> sources = surfaceVertices(spec.at, mesh);
    const Eigen::VectorXi src = Eigen::Map<const Eigen::VectorXi>(
        sources.data(), static_cast<Eigen::Index>(sources.size()));
    FeaturePointInfluence influence;
    // A pupil without its eye moves nothing: its FAPs (thrust, pupil) are disabled, and a pupil
    // placed on the lids must not drag them.
    if ((id == "3.5" && !noLeftEye.empty()) || (id == "3.6" && !noRightEye.empty())) continue;
    if (contains(fdp.eyeLeft.submeshes, sub) || contains(fdp.eyeRight.submeshes, sub)) {
      const RotationGroup& eye = contains(fdp.eyeLeft.submeshes, sub) ? in.eyeLeft : in.eyeRight;
      influence.vertices = eye.vertices;
      influence.weights.assign(eye.vertices.size(), 1.0f);
    } else if (contains(fdp.skin, sub) || contains(fdp.tongue, sub)) {
      const bool onSkin = contains(fdp.skin, sub);
      double radius = 0;
      try {
        radius = spec.radius.value_or(defaultInfluenceRadius(rig.fapu, id));
      } catch (const std::invalid_argument& e) {
        throw FileError({path, 0, 0}, "points.\"" + id + "\": no default radius (" + e.what() +
                                          "); give \"radius\"");
      }
      const GeodesicMethod m =
          onSkin ? spec.geodesics.value_or(fileMethod) : GeodesicMethod::Dijkstra;
      const InfluenceWeights& solver = !onSkin                     ? *tongueWeights
                                       : m == GeodesicMethod::Heat ? *skinHeat
                                                                   : *skinDijkstra;
      influence =
          sources.size() == 1
              ? solver.atVertex(sources[0], radius)
              : solver.atTriangle(Eigen::Vector3i(sources[0], sources[1], sources[2]), radius);
      rig.radii[id] = radius;
      rig.methods[id] = m;
      if (onSkin)
        warnUnreachedPieces(mesh, skinGraph, id, sources, fp.at(id), radius, rig.warnings);
      if (onSkin && !attached.empty()) merge(influence, attachment.weights(influence));
      // FAPs of this point that must not fold the skin over their range get an influence that
      // reaches farther along their own motion (InfluenceRadius.h, docs/rig.md "Folds"). Only
      // the brows have a range; 2.1's rigid jaw and tongue below are not added to these.
      for (int fap = 3; onSkin && fap <= kFapCount; ++fap) {
        const FapInfo& info = fapInfo(fap);
        const auto range = foldFreeRange(fap);
        if (info.motion != FapMotion::Translation || info.featurePoint != id || !range) continue;
        const DirectionalReach reach =
            directionalReach(radius, rig.fapu.unitValue(info.unit), *range);
        if (!(reach.ahead > radius || reach.behind > radius)) continue;
        FeaturePointInfluence own =
            solver.directional(src, fp.at(id), info.positiveMotion.cast<double>(), reach);
        if (!attached.empty()) merge(own, attachment.weights(own));
        in.fapInfluences[fap] = std::move(own);
        rig.reaches[fap] = reach;
      }
    } else {
      rig.warnings.push_back(
          "feature point " + id + ": sub-mesh \"" + sub +
          "\" has no deforming role (skin, tongue or eye); the point moves nothing");
    }
    if (id == "2.1") {
      std::vector<std::pair<int, float>> rigid;
      for (int v : verticesOf(mesh, fdp.jaw)) rigid.emplace_back(v, 1.0f);
      for (int v : verticesOf(mesh, fdp.tongue)) rigid.emplace_back(v, 1.0f);
      merge(influence, rigid);
    }
    if (!influence.vertices.empty()) in.influences[id] = std::move(influence);
  }

  progress(0.85, "head and tears");
  if (fdp.neckPivot) {
    rig.neckPivot = *fdp.neckPivot;
  } else {
    const auto loop = lowestBoundaryLoopCentre(mesh, fdp.skin);
    if (!loop)
      throw FileError({path, 0, 0},
                      "neck_pivot: not given, and the skin has no open boundary (neck) to "
                      "place it at; give \"neck_pivot\": [x, y, z]");
    rig.neckPivot = *loop;
  }
  in.neckPivot = rig.neckPivot.cast<float>();
  in.headVertices.resize(static_cast<std::size_t>(mesh.vertexCount()));
  for (int v = 0; v < mesh.vertexCount(); ++v) in.headVertices[static_cast<std::size_t>(v)] = v;

  const NearestVertex nearestSkin(mesh.positions, verticesOf(mesh, fdp.skin));
  const double irisd0 = rig.fapu.irisd0;
  for (auto [given, lid, out] : {std::tuple{&fdp.tearLeft, "3.3", &rig.tearLeft},
                                 std::tuple{&fdp.tearRight, "3.4", &rig.tearRight}}) {
    if (*given) {
      *out = tearSourceAt(mesh, surfaceVertices(**given, mesh).front());
      out->position = surfacePosition(**given, mesh);
    } else {
      const Eigen::Vector3d below = fp.at(lid) - Eigen::Vector3d(0.0, irisd0 / 4.0, 0.0);
      *out = tearSourceAt(mesh, nearestSkin.nearest(below));
    }
  }

  progress(0.9, "baking poses");
  PoseBakeReport report;
  rig.poses = bakePoses(in, &report);
  for (std::string& w : report.warnings) rig.warnings.push_back(std::move(w));
  progress(1.0, "done");
  return rig;
}

}  // namespace lacrima::rigging
