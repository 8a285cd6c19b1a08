#include <lacrima/scene/HeadOcclusion.h>

#include "PaintMath.h"

#include <lacrima/scene/OverlayMasks.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace lacrima::scene {
namespace {

using detail::smoothstep;

void skinCavities(const HeadMesh& head, const HeadSubmesh& skin, std::vector<float>& occlusion) {
  const std::vector<int> weld = weldCoincidentVertices(head.positions);
  const auto n = static_cast<std::size_t>(head.vertexCount());
  // 1-ring over weld roots (duplicate edges only weight a neighbour twice; harmless here).
  std::vector<std::vector<int>> ring(n);
  for (const Eigen::Vector3i& t : skin.triangles)
    for (int k = 0; k < 3; ++k) {
      const auto a = static_cast<std::size_t>(weld[static_cast<std::size_t>(t[k])]);
      const int b = weld[static_cast<std::size_t>(t[(k + 1) % 3])];
      const int c = weld[static_cast<std::size_t>(t[(k + 2) % 3])];
      ring[a].push_back(b);
      ring[a].push_back(c);
    }
  std::vector<float> value(n, 1.0f);
  for (std::size_t v = 0; v < n; ++v) {
    if (ring[v].empty()) continue;
    const Eigen::Vector3f p = head.positions.col(static_cast<Eigen::Index>(v));
    Eigen::Vector3f mean = Eigen::Vector3f::Zero();
    float edge = 0;
    for (int u : ring[v]) {
      mean += head.positions.col(u);
      edge += (head.positions.col(u) - p).norm();
    }
    const float count = static_cast<float>(ring[v].size());
    mean /= count;
    edge /= count;
    if (!(edge > 0)) continue;
    const float concavity =
        std::max(0.0f, (mean - p).dot(head.normals.col(static_cast<Eigen::Index>(v)))) / edge;
    value[v] = std::clamp(1.0f - 1.3f * concavity, 0.5f, 1.0f);
  }
  std::vector<float> next(n);
  for (int round = 0; round < 2; ++round) {
    next = value;
    for (std::size_t v = 0; v < n; ++v) {
      if (ring[v].empty()) continue;
      float sum = value[v];
      for (int u : ring[v]) sum += value[static_cast<std::size_t>(u)];
      next[v] = sum / static_cast<float>(ring[v].size() + 1);
    }
    value.swap(next);
  }
  for (int v = skin.firstVertex; v < skin.firstVertex + skin.vertexCount; ++v)
    occlusion[static_cast<std::size_t>(v)] =
        value[static_cast<std::size_t>(weld[static_cast<std::size_t>(v)])];
}

void eyeball(const HeadMesh& head, const HeadSubmesh& sub, const EyeSphere& eye,
             std::vector<float>& occlusion) {
  // The lids' skin near the eye (within 2 radii of its centre): the eyeball darkens where it
  // slips under them.
  std::vector<Eigen::Vector3f> lids;
  if (const HeadSubmesh* skin = head.findSubmesh("skin"))
    for (int v = skin->firstVertex; v < skin->firstVertex + skin->vertexCount; ++v)
      if ((head.positions.col(v) - eye.centre).norm() < 2 * eye.radius)
        lids.emplace_back(head.positions.col(v));
  for (int v = sub.firstVertex; v < sub.firstVertex + sub.vertexCount; ++v) {
    const Eigen::Vector3f p = head.positions.col(v);
    const Eigen::Vector3f d = p - eye.centre;
    const float facing = d.norm() > 0 ? d.normalized().z() : 1.0f;
    float gap = eye.radius;
    for (const Eigen::Vector3f& q : lids) gap = std::min(gap, (q - p).norm());
    const float socket = 0.5f + 0.5f * smoothstep(0.3f, 0.85f, facing);
    const float lid = 0.45f + 0.55f * smoothstep(0.02f * eye.radius, 0.35f * eye.radius, gap);
    occlusion[static_cast<std::size_t>(v)] = std::min(socket, lid);
  }
}

}  // namespace

std::vector<float> headOcclusion(const HeadMesh& head) {
  std::vector<float> occlusion(static_cast<std::size_t>(head.vertexCount()), 1.0f);
  if (head.normals.cols() != head.positions.cols()) return occlusion;
  if (const HeadSubmesh* skin = head.findSubmesh("skin")) skinCavities(head, *skin, occlusion);

  for (const auto& [eyeName, corneaName] :
       {std::pair{"eye_l", "cornea_l"}, std::pair{"eye_r", "cornea_r"}}) {
    const auto sphere = eyeSphere(head, eyeName);
    if (!sphere) continue;
    for (const char* name : {eyeName, corneaName})
      if (const HeadSubmesh* sub = head.findSubmesh(name)) eyeball(head, *sub, *sphere, occlusion);
  }

  std::vector<const HeadSubmesh*> mouth;
  float zLow = std::numeric_limits<float>::infinity(), zHigh = -zLow;
  for (const char* name : {"teeth_upper", "teeth_lower", "tongue"})
    if (const HeadSubmesh* sub = head.findSubmesh(name); sub && sub->vertexCount > 0) {
      mouth.push_back(sub);
      const auto rows = head.positions.middleCols(sub->firstVertex, sub->vertexCount).row(2);
      zLow = std::min(zLow, rows.minCoeff());
      zHigh = std::max(zHigh, rows.maxCoeff());
    }
  if (!mouth.empty() && zHigh > zLow)
    for (const HeadSubmesh* sub : mouth)
      for (int v = sub->firstVertex; v < sub->firstVertex + sub->vertexCount; ++v) {
        const float t = (head.positions(2, v) - zLow) / (zHigh - zLow);
        occlusion[static_cast<std::size_t>(v)] = 0.25f + 0.60f * smoothstep(0.2f, 1.0f, t);
      }
  return occlusion;
}

}  // namespace lacrima::scene
