#pragma once
// Small maths for what the scene computes at start-up (overlay masks and layers, the skin's
// relief, the occlusion): GLSL's smoothstep, and lattice noise, deterministic so that every run
// and every machine paints the same pixels.
#include <algorithm>
#include <cmath>
#include <cstdint>

namespace lacrima::scene::detail {

// As GLSL's: 0 below edge0, 1 above edge1 (either order), a cubic between.
inline float smoothstep(float edge0, float edge1, float x) {
  const float t = std::clamp((x - edge0) / (edge1 - edge0), 0.0f, 1.0f);
  return t * t * (3 - 2 * t);
}

// A hash of a lattice point and a seed, uniform in [0, 1].
inline float hash(int x, int y, int seed) {
  auto h = static_cast<std::uint32_t>(x) * 374761393u + static_cast<std::uint32_t>(y) * 668265263u +
           static_cast<std::uint32_t>(seed) * 2246822519u;
  h = (h ^ (h >> 13)) * 1274126177u;
  h ^= h >> 16;
  return static_cast<float>(h & 0xffffffu) / static_cast<float>(0xffffff);
}

// Smooth value noise in [0, 1], `cells` lattice cells across the unit square (tiles).
inline float valueNoise(float u, float v, int cells, int seed) {
  const float x = u * static_cast<float>(cells), y = v * static_cast<float>(cells);
  const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
  const float fx = x - static_cast<float>(x0), fy = y - static_cast<float>(y0);
  const float sx = fx * fx * (3 - 2 * fx), sy = fy * fy * (3 - 2 * fy);
  auto at = [&](int i, int j) {
    return hash(((i % cells) + cells) % cells, ((j % cells) + cells) % cells, seed);
  };
  const float a = at(x0, y0), b = at(x0 + 1, y0), c = at(x0, y0 + 1), d = at(x0 + 1, y0 + 1);
  return (a + (b - a) * sx) + ((c + (d - c) * sx) - (a + (b - a) * sx)) * sy;
}

}  // namespace lacrima::scene::detail
