#include <lacrima/scene/SkinDetail.h>

#include "PaintMath.h"

#include <lacrima/scene/OverlayMasks.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <vector>

namespace lacrima::scene {
namespace {

using detail::hash;
using detail::smoothstep;
using detail::valueNoise;

constexpr int kPoreCells = 16;
constexpr float kSlope = 0.5f;

}  // namespace

QImage makeSkinDetailNormals(int size) {
  size = std::clamp(size, 16, 2048);
  const auto texels = static_cast<std::size_t>(size) * static_cast<std::size_t>(size);
  std::vector<float> height(texels, 0.0f);
  auto at = [&](int x, int y) -> float& {
    return height[static_cast<std::size_t>(((y % size + size) % size) * size +
                                           (x % size + size) % size)];
  };

  const float cell = static_cast<float>(size) / kPoreCells;
  for (int j = 0; j < kPoreCells; ++j)
    for (int i = 0; i < kPoreCells; ++i) {
      const float cx = (static_cast<float>(i) + 0.1f + 0.8f * hash(i, j, 11)) * cell;
      const float cy = (static_cast<float>(j) + 0.1f + 0.8f * hash(i, j, 12)) * cell;
      const float radius = cell * (0.10f + 0.08f * hash(i, j, 13));
      const float depth = 0.5f + 0.5f * hash(i, j, 14);
      const int reach = static_cast<int>(std::ceil(2.5f * radius));
      for (int y = static_cast<int>(cy) - reach; y <= static_cast<int>(cy) + reach; ++y)
        for (int x = static_cast<int>(cx) - reach; x <= static_cast<int>(cx) + reach; ++x) {
          const float dx = static_cast<float>(x) + 0.5f - cx,
                      dy = static_cast<float>(y) + 0.5f - cy;
          at(x, y) -= depth * std::exp(-(dx * dx + dy * dy) / (radius * radius));
        }
    }

  for (int y = 0; y < size; ++y) {
    const float v = (static_cast<float>(y) + 0.5f) / static_cast<float>(size);
    for (int x = 0; x < size; ++x) {
      const float u = (static_cast<float>(x) + 0.5f) / static_cast<float>(size);
      const float coarse = std::abs(valueNoise(u, v, 9, 21) - 0.5f);
      const float fine = std::abs(valueNoise(u, v, 17, 22) - 0.5f);
      const float lines = 0.20f * (1 - smoothstep(0.0f, 0.06f, coarse)) +
                          0.12f * (1 - smoothstep(0.0f, 0.05f, fine));
      at(x, y) += 0.25f * (valueNoise(u, v, 64, 23) - 0.5f) - lines;
    }
  }

  QImage out(size, size, QImage::Format_RGBA8888);
  for (int y = 0; y < size; ++y) {
    uchar* row = out.scanLine(y);
    for (int x = 0; x < size; ++x) {
      const float nx = -kSlope * 0.5f * (at(x + 1, y) - at(x - 1, y));
      const float ny = -kSlope * 0.5f * (at(x, y + 1) - at(x, y - 1));
      const float length = std::sqrt(nx * nx + ny * ny + 1);
      const float n[3] = {nx / length, ny / length, 1 / length};
      for (int k = 0; k < 3; ++k)
        row[4 * x + k] = static_cast<uchar>(std::lround((n[k] * 0.5f + 0.5f) * 255.0f));
      row[4 * x + 3] = 255;
    }
  }
  return out;
}

float skinDetailTiling(const HeadMesh& head) {
  constexpr float kFallback = 64;
  const HeadSubmesh* skin = head.findSubmesh("skin");
  if (!skin || head.uvs.cols() != head.positions.cols()) return kFallback;
  std::vector<float> uvPerLength;
  uvPerLength.reserve(skin->triangles.size());
  for (const Eigen::Vector3i& t : skin->triangles) {
    const Eigen::Vector3f a = head.positions.col(t[0]);
    const float area = (Eigen::Vector3f(head.positions.col(t[1])) - a)
                           .cross(Eigen::Vector3f(head.positions.col(t[2])) - a)
                           .norm();
    const Eigen::Vector2f p = head.uvs.col(t[0]), q = head.uvs.col(t[1]), r = head.uvs.col(t[2]);
    const float uvArea = std::abs((q - p).x() * (r - p).y() - (q - p).y() * (r - p).x());
    if (area > 0 && uvArea > 0) uvPerLength.push_back(std::sqrt(uvArea / area));
  }
  if (uvPerLength.empty()) return kFallback;
  auto middle = uvPerLength.begin() + static_cast<std::ptrdiff_t>(uvPerLength.size() / 2);
  std::nth_element(uvPerLength.begin(), middle, uvPerLength.end());
  const auto eye = eyeSphere(head, "eye_l");
  const float tile =
      eye ? 1.25f * eye->radius : (head.boundsMax().y() - head.boundsMin().y()) / 16.0f;
  const float tiling = 1.0f / (*middle * tile);
  return std::isfinite(tiling) && tiling > 0 ? tiling : kFallback;
}

float skinDetailStrength(double distance, double framingDistance) {
  if (!(framingDistance > 0) || !std::isfinite(distance)) return 0;
  return smoothstep(0.75f, 0.5f, static_cast<float>(distance / framingDistance));
}

}  // namespace lacrima::scene
