#include <lacrima/rigging/RigChecks.h>

#include <lacrima/common/FapTable.h>
#include <lacrima/common/FdpTable.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <set>
#include <tuple>
#include <utility>

namespace lacrima::rigging {
namespace {

using Points = std::map<std::string, Eigen::Vector3d, FdpIdLess>;

// printf into a std::string, for the messages' figures.
template <class... Args>
std::string format(const char* pattern, Args... args) {
  char buffer[512];
  std::snprintf(buffer, sizeof buffer, pattern, args...);
  return buffer;
}

RigCheck make(RigCheck::Severity severity, std::string kind, std::vector<std::string> points,
              int fap, std::string message) {
  RigCheck c;
  c.severity = severity;
  c.kind = std::move(kind);
  c.points = std::move(points);
  c.fap = fap;
  c.message = std::move(message);
  return c;
}

// --- wrong part -------------------------------------------------------------------------------

// The role a point's sub-mesh must have, from the FDP table (see the header); "" = no surface.
std::string expectedPart(const std::string& id) {
  if (id == "3.5") return "eye_left";
  if (id == "3.6") return "eye_right";
  if (id.rfind("6.", 0) == 0) return "tongue";
  if (id == "9.8" || id == "9.10") return "upper teeth";
  if (id == "9.9" || id == "9.11") return "lower teeth";
  if (id == "7.1") return "";
  return "skin";
}

// The upper teeth stay with the skull (no role: rigid); the lower teeth follow the jaw ("jaw"),
// or stay rigid on heads whose teeth are one sub-mesh (the ICT head).
bool partFits(const std::string& expected, const std::string& role) {
  if (expected == "upper teeth") return role == "rigid";
  if (expected == "lower teeth") return role == "jaw" || role == "rigid";
  return expected == role;
}

void checkParts(const FeaturePointFile& fdp, const BuiltRig& rig, std::vector<RigCheck>& out) {
  for (const auto& [id, spec] : fdp.points) {
    const std::string expected = expectedPart(id);
    if (expected.empty()) continue;
    // A head without that eye has its pupil where it can (the "no-eyes" check reports it).
    if ((expected == "eye_left" && rig.disabled(23)) ||
        (expected == "eye_right" && rig.disabled(24)))
      continue;
    const auto found = rig.roles.find(spec.at.submesh);
    const std::string role = found == rig.roles.end() ? "none" : found->second;
    if (partFits(expected, role)) continue;
    out.push_back(make(RigCheck::Severity::Error, "wrong-part", {id}, 0,
                       "feature point " + id + " belongs on the " + expected +
                           " but sits on sub-mesh \"" + spec.at.submesh + "\" (role " + role +
                           ")"));
  }
}

// --- asymmetry --------------------------------------------------------------------------------

const std::vector<const char*>& midline() {
  static const std::vector<const char*> ids = {"2.1",  "2.2",  "2.3",  "2.10", "8.1",  "8.2",
                                               "9.3",  "9.8",  "9.9",  "9.10", "9.11", "9.12",
                                               "9.15", "11.1", "11.4", "11.5", "11.6"};
  return ids;
}

struct Plane {
  Eigen::Vector3d centre, normal;  // normal towards the face's own left
};

// The mid-sagittal plane (see the header), or nullopt when neither the midline nor the twins
// give a direction.
std::optional<Plane> midSagittalPlane(const Points& fp) {
  Eigen::Vector3d leftward = Eigen::Vector3d::Zero(), midpoints = Eigen::Vector3d::Zero();
  int pairs = 0;
  for (const auto& [l, r] : fdpMirrorPairs()) {
    const auto a = fp.find(l), b = fp.find(r);
    if (a == fp.end() || b == fp.end()) continue;
    leftward += a->second - b->second;
    midpoints += 0.5 * (a->second + b->second);
    ++pairs;
  }
  std::vector<Eigen::Vector3d> mid;
  for (const char* id : midline())
    if (const auto p = fp.find(id); p != fp.end()) mid.push_back(p->second);

  if (mid.size() >= 3) {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (const auto& p : mid) c += p;
    c /= static_cast<double>(mid.size());
    Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
    for (const auto& p : mid) scatter += (p - c) * (p - c).transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(scatter);  // ascending
    const Eigen::Vector3d lambda = eig.eigenvalues();
    Eigen::Vector3d n = eig.eigenvectors().col(0);
    // A plane needs the points to span two directions: the middle eigenvalue well above 0.
    const bool spansPlane = lambda[1] > 1e-6 * lambda[2] && lambda[2] > 0;
    if (pairs > 0 && n.dot(leftward) < 0) n = -n;
    const bool agrees = pairs == 0 || std::abs(n.dot(leftward.normalized())) > 0.5;  // < 60 deg
    if (spansPlane && agrees) return Plane{c, n};
  }
  if (pairs == 0 || leftward.norm() == 0) return std::nullopt;
  return Plane{midpoints / pairs, leftward.normalized()};
}

void checkSymmetry(const BuiltRig& rig, const RigCheckOptions& options,
                   std::vector<RigCheck>& out) {
  const Points& fp = rig.featurePoints;
  const auto plane = midSagittalPlane(fp);
  const double es0 = rig.fapu.es0;
  if (!plane || !(es0 > 0)) return;
  for (const auto& [leftId, rightId] : fdpMirrorPairs()) {
    const auto a = fp.find(leftId), b = fp.find(rightId);
    if (a == fp.end() || b == fp.end()) continue;
    const std::string l(leftId), r(rightId);
    const Eigen::Vector3d p = a->second;
    const Eigen::Vector3d mirrored =
        p - 2.0 * (p - plane->centre).dot(plane->normal) * plane->normal;
    const double off = (mirrored - b->second).norm() / es0;
    if (!(off > options.asymmetryTolerance)) continue;
    out.push_back(make(RigCheck::Severity::Warning, "asymmetry", {l, r}, 0,
                       format("%s mirrored across the mid-sagittal plane lands %.3f ES0 (%.4g "
                              "units) from its twin %s (tolerance %.3f ES0)",
                              l.c_str(), off, off * es0, r.c_str(), options.asymmetryTolerance)));
  }
}

// --- zero FAPU --------------------------------------------------------------------------------

double skinDiagonal(const HeadMesh& mesh, const FeaturePointFile& fdp) {
  Eigen::Vector3f lo = Eigen::Vector3f::Constant(std::numeric_limits<float>::infinity());
  Eigen::Vector3f hi = -lo;
  for (const std::string& name : fdp.skin) {
    const HeadSubmesh* s = mesh.findSubmesh(name);
    if (!s) continue;
    for (int v = s->firstVertex; v < s->firstVertex + s->vertexCount; ++v) {
      lo = lo.cwiseMin(mesh.positions.col(v));
      hi = hi.cwiseMax(mesh.positions.col(v));
    }
  }
  return (hi - lo).allFinite() ? static_cast<double>((hi - lo).norm()) : 0.0;
}

void checkFapu(const HeadMesh& mesh, const FeaturePointFile& fdp, const BuiltRig& rig,
               std::vector<RigCheck>& out) {
  const FapuSet& f = rig.fapu;
  const double diagonal = skinDiagonal(mesh, fdp);
  if (!(f.es0 > kNearZeroFapuOfSkinSize * diagonal))
    out.push_back(make(RigCheck::Severity::Error, "zero-fapu", {"3.5", "3.6"}, 0,
                       format("ES0 (pupil 3.5 to pupil 3.6) is %.4g units, below %.2f%% of the "
                              "skin's size %.4g: the pupils nearly coincide",
                              f.es0, 100 * kNearZeroFapuOfSkinSize, diagonal)));
  struct Unit {
    const char* name;
    double value;
    std::vector<std::string> points;
    const char* between;
  };
  const Unit units[] = {
      {"IRISD0", f.irisd0, {"3.1", "3.3", "3.2", "3.4"}, "upper to lower eyelid 3.1-3.3, 3.2-3.4"},
      {"ENS0", f.ens0, {"3.5", "3.6", "9.15"}, "eyes to nose base 9.15"},
      {"MNS0", f.mns0, {"9.15", "2.2"}, "nose base 9.15 to upper lip 2.2"},
      {"MW0", f.mw0, {"8.3", "8.4"}, "mouth corners 8.3 to 8.4"}};
  for (const Unit& u : units) {
    if (u.value > kNearZeroFapuOfEs * f.es0) continue;
    out.push_back(make(
        RigCheck::Severity::Error, "zero-fapu", u.points, 0,
        format("%s (%s) is %.4g units = %.4f ES0, below %.2f ES0: the FAPs counting "
               "in it barely move",
               u.name, u.between, u.value, f.es0 > 0 ? u.value / f.es0 : 0.0, kNearZeroFapuOfEs)));
  }
}

// --- lips joined ------------------------------------------------------------------------------

// Where a bound point goes under `pose` at `value`: its vertices' neutral positions plus their
// offsets, blended with the binding's weights.
Eigen::Vector3d posedPoint(const HeadMesh& mesh, const std::vector<std::pair<int, double>>& binding,
                           const std::map<int, Eigen::Vector3d>& offsets, double value) {
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  for (const auto& [v, w] : binding) {
    Eigen::Vector3d q = mesh.positions.col(v).cast<double>();
    if (const auto o = offsets.find(v); o != offsets.end()) q += value * o->second;
    p += w * q;
  }
  return p;
}

void checkLips(const HeadMesh& mesh, const BuiltRig& rig, std::vector<RigCheck>& out) {
  constexpr int kOpenJaw = 3;
  const VertexPose& pose = rig.poses.poses[static_cast<std::size_t>(channelIndex(kOpenJaw))];
  if (pose.empty() || !rig.bindings.count("2.1")) return;  // pose-moves-nothing says so
  std::map<int, Eigen::Vector3d> offsets;
  for (std::size_t k = 0; k < pose.vertices.size(); ++k) {
    auto [it, fresh] = offsets.try_emplace(pose.vertices[k], Eigen::Vector3d::Zero());
    it->second += pose.offsets.col(static_cast<Eigen::Index>(k)).cast<double>();
  }
  const double value = kLipsCheckOpenJaw;
  const double chin = value * rig.fapu.unitValue(FapUnit::MNS);  // how far 2.1 drops
  if (!(chin > 0)) return;                                       // zero-fapu says so
  for (const auto& [upper, lower] :
       {std::pair{"2.2", "2.3"}, std::pair{"2.6", "2.8"}, std::pair{"2.7", "2.9"}}) {
    const auto a = rig.bindings.find(upper), b = rig.bindings.find(lower);
    if (a == rig.bindings.end() || b == rig.bindings.end()) continue;
    const double before =
        (posedPoint(mesh, b->second, offsets, 0) - posedPoint(mesh, a->second, offsets, 0)).norm();
    const double after =
        (posedPoint(mesh, b->second, offsets, value) - posedPoint(mesh, a->second, offsets, value))
            .norm();
    const double growth = after - before;
    if (growth >= kLipsMinOpening * chin) continue;
    std::string shared;
    for (const auto& [va, wa] : a->second)
      for (const auto& [vb, wb] : b->second)
        if (va == vb) shared = format("; they share vertex %d", va);
    out.push_back(make(RigCheck::Severity::Error, "lips-joined", {upper, lower}, kOpenJaw,
                       format("opening the jaw (FAP 3 = %.0f) drops the chin by %.4g units but "
                              "parts the lips %s / %s by only %.4g (gap %.4g -> %.4g; at least "
                              "%.4g expected)%s",
                              value, chin, upper, lower, growth, before, after,
                              kLipsMinOpening * chin, shared.c_str())));
  }
}

// --- poses that move nothing ------------------------------------------------------------------

// The largest distance any vertex of `group` moves when it turns by `angle` about its centre.
double largestChord(const HeadMesh& mesh, const RotationGroup& group, double angle) {
  double r = 0;
  for (int v : group.vertices)
    r = std::max(r, static_cast<double>((mesh.positions.col(v) - group.centre).norm()));
  return 2.0 * r * std::abs(std::sin(0.5 * angle));
}

const RotationGroup* rotationGroupOf(const BuiltRig& rig, int fap) {
  switch (fap) {
    case 23:
    case 25:
      return &rig.poses.eyeLeft;
    case 24:
    case 26:
      return &rig.poses.eyeRight;
    case 48:
    case 49:
    case 50:
      return &rig.poses.head;
    default:
      return nullptr;
  }
}

// The FDP ids a FAP moves ("6.3;6.4" for tongue roll), those the file has.
std::vector<std::string> pointsOf(const FapInfo& info, const BuiltRig& rig) {
  std::vector<std::string> out;
  std::string_view ids = info.featurePoint;
  while (!ids.empty()) {
    const std::size_t semicolon = ids.find(';');
    const std::string id(ids.substr(0, semicolon));
    if (id == "7.1" || rig.featurePoints.count(id)) out.push_back(id);  // 7.1: the neck pivot
    ids = semicolon == std::string_view::npos ? std::string_view() : ids.substr(semicolon + 1);
  }
  return out;
}

void checkPoses(const HeadMesh& mesh, const BuiltRig& rig, std::vector<RigCheck>& out) {
  const double threshold = kPoseMovesNothingOfEs * rig.fapu.es0;
  for (int fap = 3; fap <= 68; ++fap) {
    const FapInfo& info = fapInfo(fap);
    const std::vector<std::string> points = pointsOf(info, rig);
    if (points.empty()) continue;     // no feature point: validation already warned
    if (rig.disabled(fap)) continue;  // no eye: the "no-eyes" check says so
    const double value =
        std::abs(info.sliderMax) >= std::abs(info.sliderMin) ? info.sliderMax : info.sliderMin;
    double moved = 0;
    if (const RotationGroup* group = rotationGroupOf(rig, fap)) {
      moved = largestChord(mesh, *group, value * FapuSet::kAngleUnit);
    } else {
      const VertexPose& pose = rig.poses.poses[static_cast<std::size_t>(channelIndex(fap))];
      for (Eigen::Index k = 0; k < pose.offsets.cols(); ++k)
        moved = std::max(moved, static_cast<double>(pose.offsets.col(k).norm()));
      moved *= std::abs(value);
    }
    if (moved > threshold) continue;
    std::string ids;
    for (const std::string& id : points) ids += (ids.empty() ? "" : ", ") + id;
    out.push_back(make(RigCheck::Severity::Warning, "pose-moves-nothing", points, fap,
                       format("FAP %d (%s) at %d moves no vertex by more than %.3g units (largest "
                              "%.3g) although its feature point %s exists",
                              fap, std::string(info.name).c_str(), static_cast<int>(value),
                              threshold, moved, ids.c_str())));
  }
}

// --- no eyes ----------------------------------------------------------------------------------

void checkEyes(const BuiltRig& rig, std::vector<RigCheck>& out) {
  for (const auto& [side, pupil, yaw, tears] : {std::tuple{"left", "3.5", 23, kTearLeftFap},
                                                std::tuple{"right", "3.6", 24, kTearRightFap}}) {
    if (!rig.disabled(yaw)) continue;
    out.push_back(make(RigCheck::Severity::Warning, "no-eyes", {pupil}, 0,
                       format("the head has no usable %s eye: FAPs %d, %d, %d and %d (eyeball "
                              "turns, thrust, pupil) and its tears (FAP %d) are disabled",
                              side, yaw, yaw + 2, yaw + 4, yaw + 6, tears)));
  }
}

}  // namespace

std::vector<RigCheck> checkRig(const HeadMesh& mesh, const FeaturePointFile& fdp,
                               const BuiltRig& rig, const RigCheckOptions& options) {
  std::vector<RigCheck> out;
  checkParts(fdp, rig, out);
  checkSymmetry(rig, options, out);
  checkFapu(mesh, fdp, rig, out);
  checkLips(mesh, rig, out);
  checkPoses(mesh, rig, out);
  checkEyes(rig, out);
  return out;
}

std::string toString(const RigCheck& check) {
  std::string subject;
  for (const std::string& id : check.points) subject += (subject.empty() ? "" : ", ") + id;
  if (check.fap != 0) subject += (subject.empty() ? "FAP " : "; FAP ") + std::to_string(check.fap);
  return std::string(check.severity == RigCheck::Severity::Error ? "error" : "warning") + ": " +
         check.kind + (subject.empty() ? "" : " (" + subject + ")") + ": " + check.message;
}

}  // namespace lacrima::rigging
