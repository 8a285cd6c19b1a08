#include <lacrima/scene/OverlayMasks.h>

#include "PaintMath.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

namespace lacrima::scene {
namespace {

using detail::smoothstep;

float periocularWeight(const Eigen::Vector3f& p, const EyeSphere& eye) {
  const Eigen::Vector3f d = p - eye.centre;
  if (d.z() < -0.5f * eye.radius)
    return 0;  // behind the eyeball's front half: the socket, the scalp
  const Eigen::Vector3f scaled(d.x() / 1.35f, d.y() / (d.y() < 0 ? 1.6f : 0.85f), d.z() / 2.0f);
  return 1 - smoothstep(1.15f, 2.3f, scaled.norm() / eye.radius);
}

float cheekWeight(const Eigen::Vector3f& p, const Eigen::Vector3f& normal,
                  const Eigen::Vector3f& cheek, float radius) {
  if (normal.z() < 0.2f) return 0;
  const Eigen::Vector3f d = p - cheek;
  const Eigen::Vector3f scaled(d.x() / 1.3f, d.y(), d.z());
  return 1 - smoothstep(0.3f, 1.0f, scaled.norm() / (1.9f * radius));
}

// The front-most skin vertex within half an eye radius (in x and y) of `point`, or `point`
// itself when the skin has no vertex there.
Eigen::Vector3f frontMostSkinPoint(const HeadMesh& head, const HeadSubmesh& skin,
                                   const Eigen::Vector3f& point, float reach) {
  Eigen::Vector3f best = point;
  float bestZ = -std::numeric_limits<float>::infinity();
  for (int v = skin.firstVertex; v < skin.firstVertex + skin.vertexCount; ++v) {
    const Eigen::Vector3f p = head.positions.col(v);
    if (std::abs(p.x() - point.x()) < reach && std::abs(p.y() - point.y()) < reach &&
        p.z() > bestZ) {
      bestZ = p.z();
      best = p;
    }
  }
  return best;
}

// Grows the painted region (coverage > 0) into unpainted texels by averaging painted neighbours.
void dilate(std::vector<std::array<float, 2>>& texels, std::vector<std::uint8_t>& covered, int size,
            int rounds) {
  std::vector<std::uint8_t> next;
  for (int round = 0; round < rounds; ++round) {
    next = covered;
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        const int i = y * size + x;
        if (covered[static_cast<std::size_t>(i)]) continue;
        std::array<float, 2> sum{0, 0};
        int n = 0;
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const int nx = x + dx, ny = y + dy;
            if (nx < 0 || ny < 0 || nx >= size || ny >= size) continue;
            const auto j = static_cast<std::size_t>(ny * size + nx);
            if (!covered[j]) continue;
            sum[0] += texels[j][0];
            sum[1] += texels[j][1];
            ++n;
          }
        if (n == 0) continue;
        texels[static_cast<std::size_t>(i)] = {sum[0] / static_cast<float>(n),
                                               sum[1] / static_cast<float>(n)};
        next[static_cast<std::size_t>(i)] = 1;
      }
    covered.swap(next);
  }
}

}  // namespace

std::optional<EyeSphere> eyeSphere(const HeadMesh& head, const char* submesh) {
  const HeadSubmesh* eye = head.findSubmesh(submesh);
  if (!eye || eye->vertexCount <= 0) return std::nullopt;
  const auto columns = head.positions.middleCols(eye->firstVertex, eye->vertexCount);
  const Eigen::Vector3f low = columns.rowwise().minCoeff(), high = columns.rowwise().maxCoeff();
  EyeSphere sphere;
  sphere.centre = 0.5f * (low + high);
  sphere.radius = 0.5f * (high - low).maxCoeff();
  if (!(sphere.radius > 0)) return std::nullopt;
  return sphere;
}

OverlayVertexWeights overlayVertexWeights(const HeadMesh& head) {
  OverlayVertexWeights weights;
  const auto n = static_cast<std::size_t>(head.vertexCount());
  weights.periocular.assign(n, 0.0f);
  weights.cheek.assign(n, 0.0f);
  const HeadSubmesh* skin = head.findSubmesh("skin");
  const std::array<std::optional<EyeSphere>, 2> eyes{eyeSphere(head, "eye_l"),
                                                     eyeSphere(head, "eye_r")};
  if (!skin || (!eyes[0] && !eyes[1])) return weights;

  const Eigen::Vector3f middle = 0.5f * (head.boundsMin() + head.boundsMax());
  std::array<Eigen::Vector3f, 2> cheeks;
  for (std::size_t e = 0; e < 2; ++e) {
    if (!eyes[e]) continue;
    const EyeSphere& eye = *eyes[e];
    const float outwards = eye.centre.x() >= middle.x() ? 1.0f : -1.0f;
    const Eigen::Vector3f below =
        eye.centre + Eigen::Vector3f(0.25f * eye.radius * outwards, -2.4f * eye.radius, 0);
    cheeks[e] = frontMostSkinPoint(head, *skin, below, 0.5f * eye.radius);
  }
  // The nose tip: the front-most skin between the eyes' level and well below it, on the mid line.
  std::optional<Eigen::Vector3f> nose;
  float noseReach = 0;
  if (eyes[0] && eyes[1]) {
    const float r = 0.5f * (eyes[0]->radius + eyes[1]->radius);
    const float midX = 0.5f * (eyes[0]->centre.x() + eyes[1]->centre.x());
    const float eyeY = 0.5f * (eyes[0]->centre.y() + eyes[1]->centre.y());
    float bestZ = -std::numeric_limits<float>::infinity();
    for (int v = skin->firstVertex; v < skin->firstVertex + skin->vertexCount; ++v) {
      const Eigen::Vector3f p = head.positions.col(v);
      if (std::abs(p.x() - midX) < 0.3f * r && p.y() < eyeY - r && p.y() > eyeY - 3.5f * r &&
          p.z() > bestZ) {
        bestZ = p.z();
        nose = p;
      }
    }
    noseReach = 1.1f * r;
  }
  for (int v = skin->firstVertex; v < skin->firstVertex + skin->vertexCount; ++v) {
    const Eigen::Vector3f p = head.positions.col(v);
    const Eigen::Vector3f normal = head.normals.cols() == head.positions.cols()
                                       ? Eigen::Vector3f(head.normals.col(v))
                                       : Eigen::Vector3f::UnitZ();
    float around = 0, cheek = 0;
    for (std::size_t e = 0; e < 2; ++e) {
      if (!eyes[e]) continue;
      around = std::max(around, periocularWeight(p, *eyes[e]));
      cheek = std::max(cheek, cheekWeight(p, normal, cheeks[e], eyes[e]->radius));
    }
    if (nose)
      around =
          std::max(around, 0.7f * (1 - smoothstep(0.2f, 1.0f, (p - *nose).norm() / noseReach)));
    weights.periocular[static_cast<std::size_t>(v)] = around;
    weights.cheek[static_cast<std::size_t>(v)] = cheek;
  }
  return weights;
}

QImage paintOverlayMask(const HeadMesh& head, const OverlayVertexWeights& weights, int size) {
  size = std::clamp(size, 16, 4096);
  QImage mask(size, size, QImage::Format_RGBA8888);
  mask.fill(QColor(0, 0, 0, 255));
  const HeadSubmesh* skin = head.findSubmesh("skin");
  if (!skin || head.uvs.cols() != head.positions.cols() ||
      weights.periocular.size() != static_cast<std::size_t>(head.vertexCount()))
    return mask;

  const auto texelCount = static_cast<std::size_t>(size) * static_cast<std::size_t>(size);
  std::vector<std::array<float, 2>> texels(texelCount, {0.0f, 0.0f});
  std::vector<std::uint8_t> covered(texelCount, 0);
  const float scale = static_cast<float>(size);
  for (const Eigen::Vector3i& t : skin->triangles) {
    std::array<Eigen::Vector2f, 3> uv;
    std::array<std::array<float, 2>, 3> w;
    for (int k = 0; k < 3; ++k) {
      uv[static_cast<std::size_t>(k)] = head.uvs.col(t[k]) * scale;
      const auto v = static_cast<std::size_t>(t[k]);
      w[static_cast<std::size_t>(k)] = {weights.periocular[v], weights.cheek[v]};
    }
    const float area =
        (uv[1] - uv[0]).x() * (uv[2] - uv[0]).y() - (uv[1] - uv[0]).y() * (uv[2] - uv[0]).x();
    if (std::abs(area) < 1e-12f) continue;
    const int x0 =
        std::max(0, static_cast<int>(std::floor(std::min({uv[0].x(), uv[1].x(), uv[2].x()}))));
    const int x1 = std::min(
        size - 1, static_cast<int>(std::ceil(std::max({uv[0].x(), uv[1].x(), uv[2].x()}))));
    const int y0 =
        std::max(0, static_cast<int>(std::floor(std::min({uv[0].y(), uv[1].y(), uv[2].y()}))));
    const int y1 = std::min(
        size - 1, static_cast<int>(std::ceil(std::max({uv[0].y(), uv[1].y(), uv[2].y()}))));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const Eigen::Vector2f p(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
        auto edge = [&](const Eigen::Vector2f& a, const Eigen::Vector2f& b) {
          return ((b - a).x() * (p - a).y() - (b - a).y() * (p - a).x()) / area;
        };
        const float b0 = edge(uv[1], uv[2]), b1 = edge(uv[2], uv[0]), b2 = edge(uv[0], uv[1]);
        constexpr float kSlack = -1e-4f;
        if (b0 < kSlack || b1 < kSlack || b2 < kSlack) continue;
        const auto i = static_cast<std::size_t>(y * size + x);
        texels[i] = {b0 * w[0][0] + b1 * w[1][0] + b2 * w[2][0],
                     b0 * w[0][1] + b1 * w[1][1] + b2 * w[2][1]};
        covered[i] = 1;
      }
  }
  dilate(texels, covered, size, 4);
  for (int y = 0; y < size; ++y) {
    uchar* row = mask.scanLine(y);
    for (int x = 0; x < size; ++x) {
      const auto& t = texels[static_cast<std::size_t>(y * size + x)];
      row[4 * x + 0] = static_cast<uchar>(std::lround(std::clamp(t[0], 0.0f, 1.0f) * 255.0f));
      row[4 * x + 1] = static_cast<uchar>(std::lround(std::clamp(t[1], 0.0f, 1.0f) * 255.0f));
    }
  }
  return mask;
}

}  // namespace lacrima::scene
