#include <lacrima/export/GltfAnimationExport.h>

#include "TearPieces.h"

#include <lacrima/common/FapTable.h>
#include <lacrima/common/HeadTurns.h>
#include <lacrima/exporters/GltfDocument.h>
#include <lacrima/exporters/RigExport.h>

#include <QElapsedTimer>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace lacrima::exporting {
namespace {

using exporters::GltfDocument;
using exporters::GltfHeadSkin;

enum Joint { kBody, kHead, kEyeLeft, kEyeRight };

// Rigid joints for the head's turns; vertices of an eye follow the eye, the rest of the head
// the head, everything else the body.
GltfHeadSkin headSkin(const playback::HeadRig& rig) {
  const PoseSet& poses = rig.rig.poses;
  const Eigen::Vector3f pivot = poses.head.centre;
  GltfHeadSkin skin;
  skin.joints = {{"body", -1, pivot},
                 {"head", kBody, pivot},
                 {"eye_left", kHead, poses.eyeLeft.centre},
                 {"eye_right", kHead, poses.eyeRight.centre}};
  skin.jointOfVertex.assign(static_cast<std::size_t>(rig.head.vertexCount()), kBody);
  for (int v : poses.head.vertices) skin.jointOfVertex[static_cast<std::size_t>(v)] = kHead;
  for (int v : poses.eyeLeft.vertices) skin.jointOfVertex[static_cast<std::size_t>(v)] = kEyeLeft;
  for (int v : poses.eyeRight.vertices) skin.jointOfVertex[static_cast<std::size_t>(v)] = kEyeRight;
  return skin;
}

// The tears one frame shows, as a mesh; nullopt when it shows none.
class TearMeshes {
 public:
  explicit TearMeshes(GltfDocument& document) : document_(document) {}

  std::optional<int> add(const playback::FrameView& view, int frame) {
    const std::vector<TearPiece> pieces = tearPieces(view);
    if (!pieces.empty()) ensureMaterials();
    std::vector<exporters::GltfSurface> surfaces;
    for (const TearPiece& p : pieces)
      surfaces.push_back({&p.positions, &p.normals, &p.triangles,
                          p.alpha.size() ? &p.alpha : nullptr,
                          p.kind == TearKind::Water ? water_ : film_});
    char name[32];
    std::snprintf(name, sizeof name, "tears_%04d", frame);
    return document_.addMesh(name, surfaces);
  }

 private:
  void ensureMaterials() {
    if (water_ >= 0) return;
    exporters::GltfWater water;
    water.name = "tear_water";
    water.thickness = 0.002;  // a drop is a couple of millimetres deep
    water_ = document_.addWaterMaterial(water);
    exporters::GltfWater film;
    // Wet skin looks darker and redder (it scatters less light back) and glossy: a tinted,
    // half-transparent glossy film, faded by the trail's wetness (COLOR_0's alpha). Transmission
    // would refract the skin a fraction of a millimetre below it, which renderers draw as a
    // dark seam rather than as wet skin.
    film.name = "wet_trail";
    film.baseColor = {0.42f, 0.26f, 0.22f, 0.5f};
    film.roughness = 0.1;
    film.transmission = 0;
    film.vertexAlphaBlended = true;
    film_ = document_.addWaterMaterial(film);
  }

  GltfDocument& document_;
  int water_ = -1, film_ = -1;
};

// A morph target: a FAP's pose for its positive values, or the pose negated for its negative
// values. Every weight is then at least 0, which Blender 3.4's importer needs: it widens a shape
// key's range below 0 only when the first key is negative (it reads the first value alone), and
// otherwise clamps every negative weight of the animation to 0.
struct MorphTarget {
  exporters::ExportedPose pose;
  float sign = 1;
};

// The poses named by their FAP ("open_jaw"), and a "<name>_negative" target beside each FAP
// that is negative in some exported frame.
std::vector<MorphTarget> morphTargets(std::vector<exporters::ExportedPose> poses,
                                      const FapAnimation& animation, const FrameSpan& span) {
  std::vector<MorphTarget> targets;
  for (exporters::ExportedPose& pose : poses) {
    const auto channel = static_cast<std::size_t>(channelIndex(pose.fap));
    bool negative = false;
    for (int f = span.first; f <= span.last && !negative; ++f)
      negative = usableFapValue(animation.frames[static_cast<std::size_t>(f)][channel]) < 0;
    pose.name = std::string(fapInfo(pose.fap).name);
    if (negative) {
      exporters::ExportedPose opposite = pose;
      opposite.name += "_negative";
      opposite.offsets = -pose.offsets;
      targets.push_back({std::move(pose), 1});
      targets.push_back({std::move(opposite), -1});
    } else {
      targets.push_back({std::move(pose), 1});
    }
  }
  return targets;
}

bool turns(const std::vector<Eigen::Quaternionf>& rotations) {
  return std::any_of(rotations.begin(), rotations.end(),
                     [](const Eigen::Quaternionf& q) { return q.w() < 1.0f; });
}

}  // namespace

GltfExportResult exportGltfAnimation(const playback::HeadRig& rig, const ExportOptions& options) {
  QElapsedTimer wall;
  wall.start();
  playback::Playback playback(rig);
  const FrameSpan span = openForExport(playback, options);
  const FapAnimation& animation = playback.animation();

  const std::vector<MorphTarget> targets = morphTargets(
      exporters::prepareRigExport(rig.head, rig.rig.poses, options.output), animation, span);
  std::vector<exporters::ExportedPose> poses;
  std::vector<std::string> names;
  for (const MorphTarget& target : targets) {
    poses.push_back(target.pose);
    names.push_back(target.pose.name);
  }

  GltfExportResult result;
  result.metresPerUnit = metresPerUnit(rig);
  GltfDocument document(result.metresPerUnit);
  const GltfHeadSkin skin = headSkin(rig);
  std::vector<int> joints;
  const int head = document.addHead(rig.head, poses, names, -1, &skin, &joints);
  const int tearsNode = document.addNode("tears");
  TearMeshes tearMeshes(document);

  std::vector<float> times, weights;
  std::vector<Eigen::Quaternionf> headTurns, leftTurns, rightTurns;
  std::vector<std::pair<int, int>> tearNodes;  // (frame index in the span, node)
  for (int f = span.first; f <= span.last; ++f) {
    const int k = f - span.first;
    times.push_back(static_cast<float>(k / animation.fps));
    const FapValues& values = animation.frames[static_cast<std::size_t>(f)];
    for (const MorphTarget& target : targets)
      weights.push_back(
          std::max(0.0f, target.sign *
                             usableFapValue(
                                 values[static_cast<std::size_t>(channelIndex(target.pose.fap))])) /
          exporters::kExportedPoseValue);
    headTurns.push_back(headTurn(values).cast<float>());
    leftTurns.push_back(eyeTurn(values, EyeSide::Left).cast<float>());
    rightTurns.push_back(eyeTurn(values, EyeSide::Right).cast<float>());
    // Frame f's tears as the player shows them: the tears of whole frame f.
    if (playback.hasTears()) {
      const playback::FrameView& view = playback.seek(f / animation.fps);
      if (const std::optional<int> mesh = tearMeshes.add(view, f)) {
        char name[32];
        std::snprintf(name, sizeof name, "tears_%04d", f);
        const int node = document.addNode(name, tearsNode);
        document.setMesh(node, *mesh);
        document.setScale(node, Eigen::Vector3d::Zero());
        tearNodes.emplace_back(k, node);
      }
    }
    reportProgress(options, playback, k + 1, span.count());
  }

  document.setAnimationName("lacrima");
  if (!poses.empty()) document.animateWeights(head, times, weights, static_cast<int>(poses.size()));
  if (turns(headTurns)) document.animateRotation(joints[kHead], times, headTurns);
  if (turns(leftTurns)) document.animateRotation(joints[kEyeLeft], times, leftTurns);
  if (turns(rightTurns)) document.animateRotation(joints[kEyeRight], times, rightTurns);
  // Each frame's tears show during that frame only: scale 1 from its time to the next frame's,
  // 0 before and after (STEP holds a key's value until the next key).
  const float last = times.back();
  for (const auto& [k, node] : tearNodes) {
    std::vector<float> keyTimes;
    std::vector<Eigen::Vector3f> scales;
    if (k > 0) {
      keyTimes.push_back(0.0f);
      scales.push_back(Eigen::Vector3f::Zero());
    }
    keyTimes.push_back(times[static_cast<std::size_t>(k)]);
    scales.push_back(Eigen::Vector3f::Ones());
    if (times[static_cast<std::size_t>(k)] < last) {
      keyTimes.push_back(times[static_cast<std::size_t>(k) + 1]);
      scales.push_back(Eigen::Vector3f::Zero());
    }
    document.animateScale(node, keyTimes, scales, exporters::GltfInterpolation::Step);
  }
  document.save(options.output);

  result.frames = span.count();
  result.morphTargets = static_cast<int>(targets.size());
  result.tearFrames = static_cast<int>(tearNodes.size());
  result.bytes = document.binaryBytes();
  result.seconds = static_cast<double>(wall.elapsed()) / 1000.0;
  return result;
}

}  // namespace lacrima::exporting
