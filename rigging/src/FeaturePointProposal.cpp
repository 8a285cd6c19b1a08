#include <lacrima/rigging/FeaturePointProposal.h>

#include <lacrima/rigging/ClosestSurfacePoints.h>
#include <lacrima/rigging/SphereFit.h>

#include "FeaturePointProposalFeatures.h"
#include "FeaturePointProposalLips.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <Eigen/SVD>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <stdexcept>
#include <tuple>

namespace lacrima::rigging {
namespace {

// How far the spline's correction reaches from the nearest anchor, in units of the anchors' RMS
// distance from their centroid. Chosen on the ICT head (8 anchors and the eye centres, with the
// eyes' step): 0.4 to 0.7 give a mean error of 0.076 to 0.078 ES0, 0.2, 0.3 and 1.0 0.080 and
// the undamped spline 0.082.
constexpr double kSplineReach = 0.5;

void checkAnchors(const Eigen::Matrix3Xd& source, const Eigen::Matrix3Xd& target) {
  if (source.cols() != target.cols() || source.cols() < 4)
    throw std::invalid_argument(
        "warpPoints: expected the same number (>= 4) of source and target anchors");
  // Umeyama divides by the source's spread: all anchors at one place would give NaN.
  for (const Eigen::Matrix3Xd* anchors : {&source, &target})
    if (!anchors->allFinite() ||
        !((anchors->colwise() - anchors->rowwise().mean()).squaredNorm() > 0))
      throw std::invalid_argument(
          "warpPoints: the anchors are degenerate (not finite, or all at one place)");
}

// The thin-plate spline's system [K P; P^T 0] [w; c A] = [b - a'; 0], with K_ij = |a'_i - a'_j|
// and the rows of P = [1 a'_i^T]; solved for the 3 right-hand sides at once.
Eigen::MatrixXd splineCoefficients(const Eigen::Matrix3Xd& fitted, const Eigen::Matrix3Xd& target) {
  const Eigen::Index n = fitted.cols();
  Eigen::MatrixXd system = Eigen::MatrixXd::Zero(n + 4, n + 4);
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = 0; j < n; ++j) system(i, j) = (fitted.col(i) - fitted.col(j)).norm();
    system(i, n) = system(n, i) = 1.0;
    system.block<1, 3>(i, n + 1) = fitted.col(i).transpose();
    system.block<3, 1>(n + 1, i) = fitted.col(i);
  }
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(n + 4, 3);
  rhs.topRows(n) = (target - fitted).transpose();
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(system);
  if (lu.rank() < n + 4)
    throw std::invalid_argument(
        "warpPoints: the anchors are degenerate (repeated, or all in one plane)");
  return lu.solve(rhs);
}

Eigen::Matrix3Xd positionsOf(const std::vector<const SurfacePoint*>& points, const HeadMesh& mesh) {
  Eigen::Matrix3Xd out(3, static_cast<Eigen::Index>(points.size()));
  for (std::size_t k = 0; k < points.size(); ++k)
    out.col(static_cast<Eigen::Index>(k)) = surfacePosition(*points[k], mesh);
  return out;
}

// An eye's centre of rotation, given or fitted (as RigBuilder does): an anchor deep behind the
// surface, which both heads have without anyone placing it.
std::optional<Eigen::Vector3d> eyeCentre(const EyeSpec& eye, const HeadMesh& mesh) {
  if (eye.centre) return eye.centre;
  if (eye.submeshes.empty()) return std::nullopt;
  if (const auto sphere = fitSphere(mesh, eye.submeshes)) return sphere->centre;
  return std::nullopt;
}

// The sub-meshes of each part of a head, by the role names of the file format.
std::vector<std::pair<std::string, const std::vector<std::string>*>> parts(
    const FeaturePointFile& file) {
  return {{"skin", &file.skin},
          {"eye_left", &file.eyeLeft.submeshes},
          {"eye_right", &file.eyeRight.submeshes},
          {"jaw", &file.jaw},
          {"tongue", &file.tongue}};
}

std::string partOf(const FeaturePointFile& file, const std::string& submesh) {
  for (const auto& [role, names] : parts(file))
    if (std::find(names->begin(), names->end(), submesh) != names->end()) return role;
  return {};
}

// Snaps `queries` to the vertices of the sub-meshes `names` of `mesh`: the vertex nearest the
// closest surface point. The closest surface point keeps a query on the sheet of skin under it
// (not the lining behind a lid); the nearest vertex to it, rather than the corner of its
// triangle with the largest barycentric weight, does not depend on which way the mesh's quads
// were split, so that a symmetric head gives mirror-image vertices for mirror-image queries
// (the largest-weight corner put the ICT head's cheek points 5.1 and 5.2 0.058 ES0 out of
// mirror image, its quads being split the same way on both sides).
std::vector<SurfacePoint> snapToVertices(const Eigen::Matrix3Xd& queries, const HeadMesh& mesh,
                                         const std::vector<std::string>& names) {
  std::vector<Eigen::Vector3i> triangles;
  for (const std::string& name : names) {
    const HeadSubmesh& s = *mesh.findSubmesh(name);
    triangles.insert(triangles.end(), s.triangles.begin(), s.triangles.end());
  }
  const Eigen::Matrix3Xd positions = mesh.positions.cast<double>();
  const SurfacePoints closest = closestSurfacePoints(positions, triangles, queries);
  std::vector<int> used;
  for (const Eigen::Vector3i& t : triangles) used.insert(used.end(), {t[0], t[1], t[2]});
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  Eigen::Matrix3Xd candidates(3, static_cast<Eigen::Index>(used.size()));
  for (std::size_t k = 0; k < used.size(); ++k)
    candidates.col(static_cast<Eigen::Index>(k)) = positions.col(used[k]);
  std::vector<SurfacePoint> out;
  for (Eigen::Index j = 0; j < queries.cols(); ++j) {
    if (closest.triangle[j] < 0) throw std::invalid_argument("the part has no triangle with area");
    const Eigen::Vector3i& t = triangles[static_cast<std::size_t>(closest.triangle[j])];
    const Eigen::Vector3d onSurface = positions.col(t[0]) * closest.barycentric(0, j) +
                                      positions.col(t[1]) * closest.barycentric(1, j) +
                                      positions.col(t[2]) * closest.barycentric(2, j);
    Eigen::Index nearest = 0;
    (candidates.colwise() - onSurface).colwise().squaredNorm().minCoeff(&nearest);
    const int vertex = used[static_cast<std::size_t>(nearest)];
    for (const std::string& name : names) {
      const HeadSubmesh& s = *mesh.findSubmesh(name);
      if (vertex >= s.firstVertex && vertex < s.firstVertex + s.vertexCount) {
        SurfacePoint p;
        p.submesh = name;
        p.vertex = vertex - s.firstVertex;
        out.push_back(p);
        break;
      }
    }
  }
  return out;
}

// The anchors' names in the order of the columns of the anchor matrices, for messages.
std::string anchorList(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

// Anchors that cannot define a warp get an error naming the file and the anchors, not a NaN
// later: two at one place (the spline would have to send one point to two), all on one line
// (no rotation about it is determined) or all in one plane (the spline's affine part is not).
// Relative tolerances, so that the test does not depend on the head's units.
void checkAnchorGeometry(const Eigen::Matrix3Xd& target, const std::vector<std::string>& names,
                         const std::string& path) {
  const auto fail = [&](const std::string& what) {
    throw FileError({path, 0, 0}, "points: the anchors " + what +
                                      "; place the eye corners, nose tip, mouth corners and "
                                      "chin where they are on the head");
  };
  if (!target.allFinite()) fail(anchorList(names) + " are not all finite");
  const Eigen::Matrix3Xd centred = target.colwise() - target.rowwise().mean();
  const double spread = std::sqrt(centred.squaredNorm() / static_cast<double>(target.cols()));
  constexpr double kTolerance = 1e-3;
  for (Eigen::Index i = 0; i < target.cols(); ++i)
    for (Eigen::Index j = i + 1; j < target.cols(); ++j)
      if (!((target.col(i) - target.col(j)).norm() > kTolerance * spread))
        fail(names[static_cast<std::size_t>(i)] + " and " + names[static_cast<std::size_t>(j)] +
             " are at the same place");
  // The singular values of the 3 x n spread, from its 3 x 3 scatter: a fixed-size SVD compiles
  // in a fraction of the time of a dynamic one, and the 1e-3 ratios survive the squaring.
  const Eigen::Vector3d sigma =
      Eigen::JacobiSVD<Eigen::Matrix3d>(centred * centred.transpose()).singularValues().cwiseSqrt();
  if (!(sigma[1] > kTolerance * sigma[0])) fail(anchorList(names) + " lie on one line");
  if (!(sigma[2] > kTolerance * sigma[0])) fail(anchorList(names) + " lie in one plane");
}

}  // namespace

const std::vector<std::string>& proposalAnchors() {
  static const std::vector<std::string> ids = {"2.10", "3.7", "3.8", "3.11",
                                               "3.12", "8.3", "8.4", "9.3"};
  return ids;
}

double similarityScale(const Eigen::Matrix3Xd& source, const Eigen::Matrix3Xd& target) {
  checkAnchors(source, target);
  return Eigen::umeyama(source, target, true).topLeftCorner<3, 3>().col(0).norm();
}

Eigen::Matrix3Xd warpPoints(const Eigen::Matrix3Xd& source, const Eigen::Matrix3Xd& target,
                            const Eigen::Matrix3Xd& points) {
  checkAnchors(source, target);
  const Eigen::Matrix4d similarity = Eigen::umeyama(source, target, true);
  const auto fit = [&](const Eigen::Matrix3Xd& x) -> Eigen::Matrix3Xd {
    return (similarity.topLeftCorner<3, 3>() * x).colwise() + similarity.topRightCorner<3, 1>();
  };
  const Eigen::Matrix3Xd fitted = fit(source);
  const Eigen::MatrixXd coefficients = splineCoefficients(fitted, target);
  const Eigen::Index n = fitted.cols();
  const double spread = std::sqrt((fitted.colwise() - fitted.rowwise().mean()).squaredNorm() /
                                  static_cast<double>(n));
  const double reach = kSplineReach * spread;
  Eigen::Matrix3Xd out = fit(points);
  for (Eigen::Index j = 0; j < out.cols(); ++j) {
    const Eigen::Vector3d x = out.col(j);
    Eigen::Vector3d f =
        x + coefficients.row(n).transpose() + coefficients.middleRows(n + 1, 3).transpose() * x;
    for (Eigen::Index i = 0; i < n; ++i)
      f += (x - fitted.col(i)).norm() * coefficients.row(i).transpose();
    const double d = (fitted.colwise() - x).colwise().norm().minCoeff() / reach;
    out.col(j) = x + std::exp(-d * d) * (f - x);
  }
  return out;
}

FeaturePointFile proposeFeaturePoints(const FeaturePointFile& partial, const HeadMesh& mesh,
                                      const FeaturePointFile& reference,
                                      const HeadMesh& referenceMesh, Warnings* warnings,
                                      const ProposalOptions& options, ProposalTimings* timings) {
  using Clock = std::chrono::steady_clock;
  const auto millisecondsSince = [](Clock::time_point t) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
  };
  const Clock::time_point start = Clock::now();
  std::string missing;
  for (const std::string& id : proposalAnchors())
    if (!partial.points.count(id)) missing += (missing.empty() ? "" : ", ") + id;
  if (!missing.empty())
    throw FileError({partial.path, 0, 0},
                    "points: missing anchor feature point(s) " + missing +
                        "; a partial feature-point file needs at least the eye corners 3.7, 3.8, "
                        "3.11, 3.12, the nose tip 9.3, the mouth corners 8.3, 8.4 and the chin "
                        "2.10");

  // Every point both files have is an anchor; every reference point the partial lacks, by part.
  std::vector<const SurfacePoint*> sourceAnchors, targetAnchors;
  std::vector<std::string> anchorNames;
  std::map<std::string, std::vector<std::string>> proposedByPart;
  for (const auto& [id, spec] : reference.points) {
    if (const auto given = partial.points.find(id); given != partial.points.end()) {
      sourceAnchors.push_back(&spec.at);
      targetAnchors.push_back(&given->second.at);
      anchorNames.push_back(id);
    } else {
      proposedByPart[partOf(reference, spec.at.submesh)].push_back(id);
    }
  }
  Eigen::Matrix3Xd source = positionsOf(sourceAnchors, referenceMesh);
  Eigen::Matrix3Xd target = positionsOf(targetAnchors, mesh);
  EyeCentres eyes;
  for (const auto& [side, from, to] :
       {std::tuple{"left", &reference.eyeLeft, &partial.eyeLeft},
        std::tuple{"right", &reference.eyeRight, &partial.eyeRight}}) {
    const auto a = eyeCentre(*from, referenceMesh), b = eyeCentre(*to, mesh);
    if (!a || !b) continue;
    source.conservativeResize(3, source.cols() + 1);
    target.conservativeResize(3, target.cols() + 1);
    source.rightCols<1>() = *a;
    target.rightCols<1>() = *b;
    anchorNames.push_back(std::string("the ") + side + " eye's centre");
    eyes[std::string("eye_") + side] = {*a, *b};
  }
  checkAnchorGeometry(target, anchorNames, partial.path);
  const double scale = similarityScale(source, target);

  // Every proposed point, carried by the similarity and the faded spline.
  std::vector<std::string> ids;
  std::vector<const SurfacePoint*> at;
  for (const auto& [part, partIds] : proposedByPart)
    for (const std::string& id : partIds) {
      ids.push_back(id);
      at.push_back(&reference.points.at(id).at);
    }
  Eigen::Matrix3Xd carried = warpPoints(source, target, positionsOf(at, referenceMesh));
  if (timings) timings->fitMs = millisecondsSince(start);

  const Clock::time_point eyeStart = Clock::now();
  if (options.method == ProposalMethod::FeatureAware) {
    const Eigen::Matrix3d rotation =
        Eigen::umeyama(source, target, true).topLeftCorner<3, 3>() / scale;
    placeEyePoints(ids, reference, referenceMesh, partial, mesh, eyes, rotation, scale, carried);
  }
  if (timings) timings->eyesMs = millisecondsSince(eyeStart);

  // Step 4: the inner lips on their own lips.
  const Clock::time_point mouthStart = Clock::now();
  if (options.method == ProposalMethod::FeatureAware) {
    std::map<std::string, Eigen::Vector3d> given;
    for (std::size_t k = 0; k < targetAnchors.size(); ++k)
      given[anchorNames[k]] = target.col(static_cast<Eigen::Index>(k));
    placeLipPoints(ids, mesh, partial.skin, given, partial.path, warnings, carried);
  }
  if (timings) timings->mouthMs = millisecondsSince(mouthStart);

  const Clock::time_point snapStart = Clock::now();
  FeaturePointFile out = partial;
  Eigen::Index next = 0;
  for (const auto& [part, partIds] : proposedByPart) {
    const Eigen::Index first = next;
    next += static_cast<Eigen::Index>(partIds.size());
    const std::vector<std::string>* names = nullptr;
    for (const auto& [role, roleNames] : parts(partial))
      if (role == part && !roleNames->empty()) names = roleNames;
    if (!names) {
      if (warnings)
        for (const std::string& id : partIds)
          warnings->push_back(Diagnostic{SourceLocation{partial.path, 0, 0},
                                         "no feature point " + id +
                                             " proposed: the head has no sub-mesh in role \"" +
                                             part + "\" for it"});
      continue;
    }
    const std::vector<SurfacePoint> snapped = snapToVertices(
        carried.middleCols(first, static_cast<Eigen::Index>(partIds.size())), mesh, *names);
    for (std::size_t k = 0; k < partIds.size(); ++k) {
      FeaturePointSpec spec = reference.points.at(partIds[k]);
      spec.at = snapped[k];
      if (spec.radius) *spec.radius *= scale;
      out.points[partIds[k]] = spec;
    }
  }
  if (timings) timings->snapMs = millisecondsSince(snapStart);
  return out;
}

}  // namespace lacrima::rigging
