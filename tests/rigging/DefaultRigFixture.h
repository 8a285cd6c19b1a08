#pragma once
// The default head rigged in memory from media/default-head.fdp.json and posed through
// PoseBlender, the player's blend: the set-up shared by the suites that judge poses on the
// real head (AttachedCardsTest, SkinFoldTest). Without the head in the cache the rig is empty
// and the suites skip (REQUIRE_DEFAULT_RIG).

#include "../support/MissingData.h"

#include <lacrima/common/FapChannels.h>
#include <lacrima/common/FapReader.h>
#include <lacrima/common/HeadMesh.h>
#include <lacrima/common/PoseSet.h>
#include <lacrima/rigging/DefaultHead.h>
#include <lacrima/rigging/FeaturePointFile.h>
#include <lacrima/rigging/RigBuilder.h>

#include <QString>

#include <initializer_list>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace lacrima::testrig {

inline const QString kDefaultFdp =
    QStringLiteral(LACRIMA_SOURCE_DIR "/media/default-head.fdp.json");
inline const QString kDemo = QStringLiteral(LACRIMA_SOURCE_DIR "/media/demo/crying.fap");

// The default head is in decimetres: 0.01 units = 1 mm.
inline constexpr double kMillimetre = 0.01;

struct DefaultRig {
  std::unique_ptr<HeadMesh> head;
  std::unique_ptr<rigging::BuiltRig> rig;
  std::unique_ptr<PoseBlender> blender;
  std::vector<Eigen::Vector3i> skinTriangles;  // every triangle of the skin sub-meshes
  std::vector<int> skinVertices;               // their vertex ranges

  explicit operator bool() const { return head != nullptr; }

  bool hasRole(const HeadSubmesh& s, const char* role) const {
    const auto found = rig->roles.find(s.name);
    return found != rig->roles.end() && found->second == role;
  }

  // "vertex 10827 (eyebrows)", or "-" for -1.
  QString where(int vertex) const {
    if (vertex < 0) return "-";
    return QString("vertex %1 (%2)")
        .arg(vertex)
        .arg(head->submeshes[static_cast<std::size_t>(head->submeshOfVertex(vertex))].name.c_str());
  }
};

// Rigs the default head, or returns an empty rig when it is not in the cache. Throws what
// reading the feature-point file or building the rig throws.
inline DefaultRig loadDefaultRig() {
  DefaultRig out;
  if (!rigging::defaultHeadAvailable()) return out;
  out.head = std::make_unique<HeadMesh>(rigging::loadDefaultHead());
  Warnings warnings;
  const rigging::FeaturePointFile fdp =
      rigging::readFeaturePointFile(kDefaultFdp.toStdString(), &warnings);
  rigging::validateFeaturePoints(fdp, *out.head, &warnings);
  out.rig = std::make_unique<rigging::BuiltRig>(rigging::buildRig(*out.head, fdp));
  out.blender = std::make_unique<PoseBlender>(*out.head, out.rig->poses);
  for (const HeadSubmesh& s : out.head->submeshes) {
    if (!out.hasRole(s, "skin")) continue;
    out.skinTriangles.insert(out.skinTriangles.end(), s.triangles.begin(), s.triangles.end());
    for (int v = 0; v < s.vertexCount; ++v) out.skinVertices.push_back(s.firstVertex + v);
  }
  return out;
}

// FAP values with the listed channels set and every other at 0.
inline FapValues fapValues(std::initializer_list<std::pair<int, double>> values) {
  FapValues v{};
  for (const auto& [fap, value] : values)
    v[static_cast<std::size_t>(channelIndex(fap))] = static_cast<float>(value);
  return v;
}

// Every frame of the demo (media/demo/crying.fap).
inline std::vector<FapValues> demoFrames() {
  return FapReader::readFile(kDemo.toStdString()).animation.frames;
}

}  // namespace lacrima::testrig

#define REQUIRE_DEFAULT_RIG(fixture)                     \
  do {                                                   \
    if (!(fixture)) LACRIMA_SKIP_WITHOUT_DEFAULT_HEAD(); \
  } while (false)
