// Texture-blend weights (Overlays.h).
#include "Overlays.h"

#include <lacrima/tears/TearSimulation.h>

#include <algorithm>
#include <cmath>

namespace lacrima::playback {

namespace {

double unit(double x) { return std::isfinite(x) ? std::clamp(x, 0.0, 1.0) : 0.0; }

}  // namespace

OverlayWeights overlayWeights(const SceneSettings& scene, double progress,
                              const tears::TearSimulation* simulation, const KeyedColours& keyed) {
  OverlayWeights w;
  if (!scene.textureBlending) return w;
  std::array<tears::EyeWetness, 2> wet{};
  if (simulation)
    wet = {simulation->wetness(tears::Eye::Left), simulation->wetness(tears::Eye::Right)};
  w.redness = scene.redness == SceneSettings::Redness::Animation
                  ? unit(progress)
                  : unit(0.5 * (wet[0].skin + wet[1].skin));
  if (keyed.redness) w.redness = unit(*keyed.redness);
  w.wetEyes = {unit(wet[0].eye), unit(wet[1].eye)};
  w.blush = scene.blush ? unit(keyed.blush.value_or(w.redness)) : 0.0;
  return w;
}

}  // namespace lacrima::playback
