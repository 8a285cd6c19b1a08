#include <lacrima/scene/OverlayTextures.h>

#include "PaintMath.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace lacrima::scene {
namespace {

using detail::valueNoise;

// Decoding table: 8-bit sRGB-ish (gamma 2.2, as the shaders assume) to linear.
const std::array<float, 256>& linearTable() {
  static const std::array<float, 256> table = [] {
    std::array<float, 256> t{};
    for (int i = 0; i < 256; ++i)
      t[static_cast<std::size_t>(i)] = std::pow(static_cast<float>(i) / 255.0f, 2.2f);
    return t;
  }();
  return table;
}

// Encoding through a table of 4096 linear steps (finer than 8 bits where it matters): a pow per
// channel per texel made the layers the slowest part of loading a head.
uchar encode(float linear) {
  static const std::array<uchar, 4097> table = [] {
    std::array<uchar, 4097> t{};
    for (int i = 0; i <= 4096; ++i)
      t[static_cast<std::size_t>(i)] =
          static_cast<uchar>(std::lround(std::pow(float(i) / 4096.0f, 1.0f / 2.2f) * 255.0f));
    return t;
  }();
  return table[static_cast<std::size_t>(std::lround(std::clamp(linear, 0.0f, 1.0f) * 4096.0f))];
}

QImage rgba(const QImage& image) {
  if (image.isNull()) {
    QImage white(1, 1, QImage::Format_RGBA8888);
    white.fill(Qt::white);
    return white;
  }
  return image.convertToFormat(QImage::Format_RGBA8888);
}

// Calls shade(u, v, linear rgb, alpha) for every texel of `image` (uv at texel centres); it may
// change the alpha, and when it returns true the linear colour it leaves is encoded back into the
// texel (otherwise the texel's colour is kept bit for bit).
template <typename Shade>
QImage shadeTexels(const QImage& image, Shade shade) {
  QImage out = rgba(image);
  const auto& lin = linearTable();
  const int w = out.width(), h = out.height();
  for (int y = 0; y < h; ++y) {
    uchar* row = out.scanLine(y);
    const float v = (static_cast<float>(y) + 0.5f) / static_cast<float>(h);
    for (int x = 0; x < w; ++x) {
      const float u = (static_cast<float>(x) + 0.5f) / static_cast<float>(w);
      uchar* p = row + 4 * x;
      std::array<float, 3> c{lin[p[0]], lin[p[1]], lin[p[2]]};
      if (!shade(u, v, c, p[3])) continue;
      for (int k = 0; k < 3; ++k) p[k] = encode(c[static_cast<std::size_t>(k)]);
    }
  }
  return out;
}

// Sclera: bright and nearly grey (in linear light), 0 for the iris and the pupil.
float scleraWeight(float r, float g, float b) {
  const float high = std::max({r, g, b}), low = std::min({r, g, b});
  const float saturation = high > 0 ? (high - low) / high : 0;
  return std::clamp((0.30f - saturation) / 0.12f, 0.0f, 1.0f) *
         std::clamp((high - 0.12f) / 0.15f, 0.0f, 1.0f);
}

}  // namespace

QImage makeIrritatedSkin(const QImage& skinDiffuse) {
  return shadeTexels(skinDiffuse, [](float u, float v, std::array<float, 3>& c, uchar&) {
    const float mottle = 0.65f * valueNoise(u, v, 20, 1) + 0.35f * valueNoise(u, v, 60, 2);
    const float m = 0.82f + 0.30f * mottle;
    c[0] *= 0.92f;
    c[1] *= 0.56f * m;
    c[2] *= 0.66f * m;
    return true;
  });
}

QImage makeWetEye(const QImage& eyeDiffuse) {
  return shadeTexels(eyeDiffuse, [](float u, float v, std::array<float, 3>& c, uchar& alpha) {
    auto& [r, g, b] = c;
    const float sclera = scleraWeight(r, g, b);
    alpha = static_cast<uchar>(std::lround(sclera * 255.0f));
    // Not re-encoded off the sclera: the iris and pupil keep their texels bit for bit.
    if (sclera <= 0) return false;
    // Vessels: long winding lines where warped noise crosses 0.5, and finer twigs between.
    const float warp = 0.025f * (valueNoise(u, v, 40, 8) - 0.5f);
    const float trunk = std::abs(valueNoise(u + warp, v - warp, 16, 7) - 0.5f);
    const float twig = std::abs(valueNoise(u - warp, v + warp, 48, 9) - 0.5f);
    const float vessel = std::max(std::clamp(1.0f - trunk / 0.035f, 0.0f, 1.0f),
                                  0.6f * std::clamp(1.0f - twig / 0.025f, 0.0f, 1.0f));
    // At full strength: the alpha (the sclera weight) says how much of it shows.
    g *= 0.64f;
    b *= 0.66f;
    const float redVessel = 0.8f * vessel;
    r = r * (1 - redVessel) + 0.50f * redVessel;
    g = g * (1 - redVessel) + 0.05f * redVessel;
    b = b * (1 - redVessel) + 0.05f * redVessel;
    const float film = 1.04f;  // a film of water scatters a little more light
    for (float& channel : c) channel *= film;
    return true;
  });
}

QImage padUvIslands(const QImage& texture, const HeadMesh& head, const HeadSubmesh& submesh,
                    int grow) {
  QImage out = rgba(texture);
  if (texture.isNull() || head.uvs.cols() != head.positions.cols() || submesh.triangles.empty())
    return out;
  const int w = out.width(), h = out.height();
  std::vector<std::uint8_t> covered(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), 0);
  for (const Eigen::Vector3i& t : submesh.triangles) {
    std::array<Eigen::Vector2f, 3> p;
    for (int k = 0; k < 3; ++k)
      p[static_cast<std::size_t>(k)] =
          head.uvs.col(t[k]).cwiseProduct(Eigen::Vector2f(float(w), float(h)));
    const float area =
        (p[1] - p[0]).x() * (p[2] - p[0]).y() - (p[1] - p[0]).y() * (p[2] - p[0]).x();
    if (std::abs(area) < 1e-12f) continue;
    const int x0 = std::max(0, int(std::floor(std::min({p[0].x(), p[1].x(), p[2].x()}))));
    const int x1 = std::min(w - 1, int(std::ceil(std::max({p[0].x(), p[1].x(), p[2].x()}))));
    const int y0 = std::max(0, int(std::floor(std::min({p[0].y(), p[1].y(), p[2].y()}))));
    const int y1 = std::min(h - 1, int(std::ceil(std::max({p[0].y(), p[1].y(), p[2].y()}))));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const Eigen::Vector2f c(float(x) + 0.5f, float(y) + 0.5f);
        auto side = [&](const Eigen::Vector2f& a, const Eigen::Vector2f& b) {
          return ((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x()) / area;
        };
        if (side(p[1], p[2]) >= 0 && side(p[2], p[0]) >= 0 && side(p[0], p[1]) >= 0)
          covered[static_cast<std::size_t>(y * w + x)] = 1;
      }
  }
  auto at = [&](int x, int y) { return covered[static_cast<std::size_t>(y * w + x)]; };
  // Drop the border ring: a covered texel stays only if its four neighbours are covered too.
  std::vector<std::uint8_t> inner(covered.size(), 0);
  for (int y = 1; y < h - 1; ++y)
    for (int x = 1; x < w - 1; ++x)
      inner[static_cast<std::size_t>(y * w + x)] =
          at(x, y) && at(x - 1, y) && at(x + 1, y) && at(x, y - 1) && at(x, y + 1);
  covered.swap(inner);
  std::vector<std::uint8_t> next;
  for (int round = 0; round < grow + 1; ++round) {
    next = covered;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        if (at(x, y)) continue;
        int sum[3] = {0, 0, 0}, n = 0;
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const int nx = x + dx, ny = y + dy;
            if (nx < 0 || ny < 0 || nx >= w || ny >= h || !at(nx, ny)) continue;
            const uchar* q = out.constScanLine(ny) + 4 * nx;
            for (int c = 0; c < 3; ++c) sum[c] += q[c];
            ++n;
          }
        if (n == 0) continue;
        uchar* q = out.scanLine(y) + 4 * x;
        for (int c = 0; c < 3; ++c) q[c] = static_cast<uchar>(sum[c] / n);
        next[static_cast<std::size_t>(y * w + x)] = 1;
      }
    covered.swap(next);
  }
  return out;
}

}  // namespace lacrima::scene
