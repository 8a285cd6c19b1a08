// The face frame and the nearest axis-aligned rotation (FaceFrame.h).
#include <lacrima/rigging/FaceFrame.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

namespace lacrima::rigging {
namespace {

// For row i of a rotation in G24: the one column j it reads and its sign.
struct AxisMove {
  int from = 0;
  double sign = 1;
};

std::array<AxisMove, 3> axisMoves(const Eigen::Matrix3d& rotation) {
  std::array<AxisMove, 3> moves;
  for (int i = 0; i < 3; ++i) {
    Eigen::Index j = 0;
    rotation.row(i).cwiseAbs().maxCoeff(&j);
    moves[static_cast<std::size_t>(i)] = {static_cast<int>(j), rotation(i, j) < 0 ? -1.0 : 1.0};
  }
  return moves;
}

std::optional<Eigen::Vector3d> pointOf(const FeaturePointFile& fdp, const HeadMesh& mesh,
                                       const char* id) {
  const auto found = fdp.points.find(id);
  if (found == fdp.points.end()) return std::nullopt;
  return surfacePosition(found->second.at, mesh);
}

std::optional<Eigen::Vector3d> midpointOf(const FeaturePointFile& fdp, const HeadMesh& mesh,
                                          const char* a, const char* b) {
  const auto pa = pointOf(fdp, mesh, a), pb = pointOf(fdp, mesh, b);
  if (pa && pb) return 0.5 * (*pa + *pb);
  return std::nullopt;
}

// Point `a`, else the mid-point of `b` and `c`.
std::optional<Eigen::Vector3d> pointOrMidpoint(const FeaturePointFile& fdp, const HeadMesh& mesh,
                                               const char* a, const char* b, const char* c) {
  if (auto p = pointOf(fdp, mesh, a)) return p;
  return midpointOf(fdp, mesh, b, c);
}

std::string matrixText(const Eigen::Matrix3d& m) {
  std::string text = "[";
  for (int i = 0; i < 3; ++i) {
    text += i ? ", [" : "[";
    for (int j = 0; j < 3; ++j) text += (j ? ", " : "") + std::to_string(static_cast<int>(m(i, j)));
    text += "]";
  }
  return text + "]";
}

}  // namespace

std::optional<Eigen::Matrix3d> faceAxes(const Eigen::Vector3d& leftEye,
                                        const Eigen::Vector3d& rightEye,
                                        const Eigen::Vector3d& mouth) {
  const Eigen::Vector3d across = leftEye - rightEye;
  const Eigen::Vector3d up = 0.5 * (leftEye + rightEye) - mouth;
  if (!across.allFinite() || !up.allFinite() || !(across.norm() > 0) || !(up.norm() > 0))
    return std::nullopt;
  const Eigen::Vector3d x = across.normalized();
  const Eigen::Vector3d upright = up - up.dot(x) * x;
  // A mouth within ~6 degrees of the eye line gives no usable up direction.
  if (!(upright.norm() > 0.1 * up.norm())) return std::nullopt;
  Eigen::Matrix3d axes;
  axes.col(0) = x;
  axes.col(1) = upright.normalized();
  axes.col(2) = axes.col(0).cross(axes.col(1));
  return axes;
}

std::optional<Eigen::Matrix3d> faceAxes(const FeaturePointFile& fdp, const HeadMesh& mesh) {
  const auto left = pointOrMidpoint(fdp, mesh, "3.5", "3.7", "3.11");
  const auto right = pointOrMidpoint(fdp, mesh, "3.6", "3.8", "3.12");
  auto mouth = midpointOf(fdp, mesh, "8.3", "8.4");
  if (!mouth) mouth = pointOf(fdp, mesh, "2.10");
  if (!left || !right || !mouth) return std::nullopt;
  return faceAxes(*left, *right, *mouth);
}

Eigen::Matrix3d nearestAxisRotation(const Eigen::Matrix3d& axes) {
  // trace(R A) = sum_i s_i A(p_i, i) for R(i, p_i) = s_i: every permutation p and sign pattern
  // s with det R = sign(p) s_0 s_1 s_2 = +1.
  std::array<int, 3> p{0, 1, 2};
  Eigen::Matrix3d best = Eigen::Matrix3d::Identity();
  double bestTrace = -std::numeric_limits<double>::infinity();
  do {
    // The parity of a permutation of three: even for the identity and the two 3-cycles.
    const int inversions = (p[0] > p[1]) + (p[0] > p[2]) + (p[1] > p[2]);
    const double parity = inversions % 2 == 0 ? 1.0 : -1.0;
    for (int signs = 0; signs < 8; ++signs) {
      const std::array<double, 3> s{signs & 1 ? -1.0 : 1.0, signs & 2 ? -1.0 : 1.0,
                                    signs & 4 ? -1.0 : 1.0};
      if (parity * s[0] * s[1] * s[2] < 0) continue;
      double trace = 0;
      for (int i = 0; i < 3; ++i) trace += s[static_cast<std::size_t>(i)] * axes(p[i], i);
      if (trace > bestTrace) {
        bestTrace = trace;
        best.setZero();
        for (int i = 0; i < 3; ++i) best(i, p[static_cast<std::size_t>(i)]) = s[i];
      }
    }
  } while (std::next_permutation(p.begin(), p.end()));
  return best;
}

double rotationDegrees(const Eigen::Matrix3d& rotation) {
  const double c = std::clamp((rotation.trace() - 1.0) / 2.0, -1.0, 1.0);
  return std::acos(c) * 180.0 / EIGEN_PI;
}

FaceFrame measureFaceFrame(const FeaturePointFile& fdp, const HeadMesh& mesh) {
  FaceFrame frame;
  const auto axes = faceAxes(fdp, mesh);
  if (!axes) return frame;
  frame.wasMeasured = true;
  frame.measured = *axes;
  frame.rotation = nearestAxisRotation(*axes);
  frame.tiltDegrees = rotationDegrees(frame.rotation * *axes);
  return frame;
}

void applyAxisRotation(const Eigen::Matrix3d& rotation, Eigen::Matrix3Xf& columns) {
  const auto moves = axisMoves(rotation);
  const Eigen::Matrix3Xf in = columns;
  for (int i = 0; i < 3; ++i) {
    const AxisMove& m = moves[static_cast<std::size_t>(i)];
    if (m.sign > 0)
      columns.row(i) = in.row(m.from);
    else
      columns.row(i) = -in.row(m.from);
  }
}

Eigen::Vector3d applyAxisRotation(const Eigen::Matrix3d& rotation, const Eigen::Vector3d& x) {
  const auto moves = axisMoves(rotation);
  Eigen::Vector3d out;
  for (int i = 0; i < 3; ++i) {
    const AxisMove& m = moves[static_cast<std::size_t>(i)];
    out[i] = m.sign > 0 ? x[m.from] : -x[m.from];
  }
  return out;
}

FaceFrame bringToFaceFrame(HeadMesh& mesh, FeaturePointFile& fdp, Warnings* warnings) {
  const FaceFrame frame = measureFaceFrame(fdp, mesh);
  auto warn = [&](const std::string& message) {
    if (!warnings) return;
    Diagnostic d;  // member by member: GCC 12 warns about an aggregate initialiser here
    d.where.file = fdp.path;
    d.message = message;
    warnings->push_back(std::move(d));
  };
  if (!frame.wasMeasured) {
    warn(
        "cannot tell which way the face looks (it needs the pupils 3.5 and 3.6, or the eye "
        "corners 3.7, 3.11, 3.8, 3.12, and the mouth corners 8.3, 8.4 or the chin 2.10, at "
        "distinct places); the head is used as modelled: +y up, face towards +z");
    return frame;
  }
  if (frame.tiltDegrees > kFaceTiltWarningDegrees) {
    char degrees[32];
    std::snprintf(degrees, sizeof degrees, "%.0f", frame.tiltDegrees);
    warn(std::string("the face is turned ") + degrees +
         " degrees from the nearest axis (measured from the eyes and the mouth); it is used as "
         "modelled after the axis rotation " +
         matrixText(frame.rotation) +
         ", so tears fall along the model's down, not towards the chin");
  }
  if (frame.rotation.isIdentity()) return frame;

  const Eigen::Matrix3d& r = frame.rotation;
  applyAxisRotation(r, mesh.positions);
  applyAxisRotation(r, mesh.normals);
  for (EyeSpec* eye : {&fdp.eyeLeft, &fdp.eyeRight})
    if (eye->centre) eye->centre = applyAxisRotation(r, *eye->centre);
  if (fdp.neckPivot) fdp.neckPivot = applyAxisRotation(r, *fdp.neckPivot);
  auto rotatePosition = [&](SurfacePoint& p) {
    if (p.position) p.position = applyAxisRotation(r, *p.position);
  };
  for (auto& [id, spec] : fdp.points) rotatePosition(spec.at);
  for (std::optional<SurfacePoint>* tear : {&fdp.tearLeft, &fdp.tearRight})
    if (*tear) rotatePosition(**tear);
  return frame;
}

}  // namespace lacrima::rigging
