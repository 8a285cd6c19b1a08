#include "FeaturePointProposalFeatures.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include <Eigen/Geometry>

namespace lacrima::rigging {
namespace {

// An eye's cornea must stand out of its sphere by this factor for its gaze to be found, and its
// cap is what stands out by more than this fraction of the bulge (see frontOf).
constexpr double kMinimumBulge = 1.03;
constexpr double kCapDepth = 0.3;
// Gazes that differ by more than 30 degrees from the carried one are not believed (an eye
// modelled looking sideways, or a bulge that is not a cornea): the similarity's rotation stays.
const double kMaximumGazeCosine = std::cos(30.0 * EIGEN_PI / 180.0);

struct EyeSide {
  const char* role;
  const EyeSpec& (*spec)(const FeaturePointFile&);
  const char* pupil;
  std::array<const char*, 4> lids;  // the points above and below the pupil
};

const EyeSpec& leftEye(const FeaturePointFile& f) { return f.eyeLeft; }
const EyeSpec& rightEye(const FeaturePointFile& f) { return f.eyeRight; }

const EyeSide kSides[] = {
    {"eye_left", leftEye, "3.5", {"3.1", "3.3", "3.9", "3.13"}},
    {"eye_right", rightEye, "3.6", {"3.2", "3.4", "3.10", "3.14"}},
};

struct EyeFront {
  Eigen::Vector3d gaze;  // unit
  double apex = 0;       // the cornea's farthest distance from the centre
};

// Where an eye looks: from its centre to the middle of its cornea, the cap of its front half
// (the side `front` points to) that bulges out of the eyeball's sphere: the vertices farther
// from the centre than r + 0.3 (a - r), r the median distance and a the farthest. Only the
// front half, as an eyeball may be longer than wide (the ICT head's is), its back as far out as
// its cornea. nullopt for an eye without a bulge of at least 3% of r (a plain sphere has no
// front to find).
std::optional<EyeFront> frontOf(const HeadMesh& mesh, const std::vector<std::string>& parts,
                                const Eigen::Vector3d& centre, const Eigen::Vector3d& front) {
  std::vector<Eigen::Vector3d> points;
  for (const std::string& name : parts)
    if (const HeadSubmesh* s = mesh.findSubmesh(name))
      for (int v = s->firstVertex; v < s->firstVertex + s->vertexCount; ++v)
        if (const Eigen::Vector3d p = mesh.positions.col(v).cast<double>();
            (p - centre).dot(front) > 0)
          points.push_back(p);
  if (points.empty()) return std::nullopt;
  std::vector<double> distance;
  for (const Eigen::Vector3d& p : points) distance.push_back((p - centre).norm());
  std::vector<double> sorted = distance;
  std::nth_element(sorted.begin(), sorted.begin() + static_cast<long>(sorted.size() / 2),
                   sorted.end());
  const double median = sorted[sorted.size() / 2];
  const double farthest = *std::max_element(distance.begin(), distance.end());
  if (!(farthest > kMinimumBulge * median)) return std::nullopt;
  Eigen::Vector3d cap = Eigen::Vector3d::Zero();
  int count = 0;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (distance[i] >= median + kCapDepth * (farthest - median)) cap += points[i], ++count;
  const Eigen::Vector3d gaze = cap / count - centre;
  if (!(gaze.norm() > 0)) return std::nullopt;
  return EyeFront{gaze.normalized(), farthest};
}

}  // namespace

void placeEyePoints(const std::vector<std::string>& ids, const FeaturePointFile& reference,
                    const HeadMesh& referenceMesh, const FeaturePointFile& partial,
                    const HeadMesh& mesh, const EyeCentres& eyes, const Eigen::Matrix3d& rotation,
                    double scale, Eigen::Matrix3Xd& carried) {
  const auto column = [&](const std::string& id) -> Eigen::Index {
    const auto it = std::find(ids.begin(), ids.end(), id);
    return it == ids.end() ? -1 : static_cast<Eigen::Index>(it - ids.begin());
  };
  const Eigen::Vector3d leftRight = rotation.col(0);
  for (const EyeSide& side : kSides) {
    const auto eye = eyes.find(side.role);
    if (eye == eyes.end()) continue;
    // (1) Points on the eye, rigidly about its centre: the similarity's rotation, turned further
    // by the least rotation that takes the reference eye's gaze (so carried) onto this eye's.
    const std::vector<std::string>& eyeParts = side.spec(reference).submeshes;
    Eigen::Matrix3d turn = rotation;
    const auto from =
        frontOf(referenceMesh, eyeParts, eye->second.reference, Eigen::Vector3d::UnitZ());
    const auto to =
        from ? frontOf(mesh, side.spec(partial).submeshes, eye->second.head, rotation * from->gaze)
             : std::nullopt;
    if (from && to && (rotation * from->gaze).dot(to->gaze) > kMaximumGazeCosine)
      turn =
          Eigen::Quaterniond::FromTwoVectors(rotation * from->gaze, to->gaze).toRotationMatrix() *
          rotation;
    for (std::size_t k = 0; k < ids.size(); ++k) {
      const SurfacePoint& at = reference.points.at(ids[k]).at;
      if (std::find(eyeParts.begin(), eyeParts.end(), at.submesh) == eyeParts.end()) continue;
      // On the eye's outer surface in that direction (the cornea over the pupil, not the iris
      // inside it: the snap takes the nearest vertex, and the pupil is a hole in the iris).
      const Eigen::Vector3d direction =
          turn * (surfacePosition(at, referenceMesh) - eye->second.reference);
      const double radius = to ? to->apex : scale * direction.norm();
      carried.col(static_cast<Eigen::Index>(k)) =
          eye->second.head + radius * direction.normalized();
    }
    // (2) The lid points onto the pupil's vertical plane.
    Eigen::Vector3d pupil;
    if (const auto given = partial.points.find(side.pupil); given != partial.points.end())
      pupil = surfacePosition(given->second.at, mesh);
    else if (const Eigen::Index c = column(side.pupil); c >= 0)
      pupil = carried.col(c);
    else
      continue;
    // (3) A lid the warp left inside the eye out onto it.
    for (const char* lid : side.lids)
      if (const Eigen::Index c = column(lid); c >= 0) {
        carried.col(c) += leftRight * leftRight.dot(pupil - carried.col(c));
        const Eigen::Vector3d out = carried.col(c) - eye->second.head;
        if (to && out.norm() < to->apex)
          carried.col(c) = eye->second.head + to->apex * out.normalized();
      }
  }
}

}  // namespace lacrima::rigging
