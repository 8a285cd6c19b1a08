#include <lacrima/player/HeadViews.h>

namespace lacrima::player {
namespace {

// An eye's centre: the rig's (fitted to the eyeball or given in the feature-point file), else
// its pupil point, which sits on the eye's front a fraction of ES0 away: close enough to aim at.
std::optional<Eigen::Vector3d> eyeCentre(const rigging::BuiltRig& rig,
                                         const std::optional<Eigen::Vector3d>& fitted,
                                         const char* pupil) {
  if (fitted) return fitted;
  if (const auto point = rig.featurePoints.find(pupil); point != rig.featurePoints.end())
    return point->second;
  return std::nullopt;
}

}  // namespace

std::optional<scene::FaceLandmarks> faceLandmarks(const playback::HeadRig& rig) {
  const auto left = eyeCentre(rig.rig, rig.rig.eyeCentreLeft, "3.5");
  const auto right = eyeCentre(rig.rig, rig.rig.eyeCentreRight, "3.6");
  const auto chin = rig.rig.featurePoints.find("2.1");
  if (!left || !right || chin == rig.rig.featurePoints.end()) return std::nullopt;
  return scene::FaceLandmarks{*left, *right, chin->second, rig.rig.fapu.es0};
}

scene::OrbitView presetView(const playback::HeadRig& rig, scene::CameraPreset preset) {
  if (const auto face = faceLandmarks(rig)) return scene::presetView(rig.head, preset, *face);
  return scene::presetView(rig.head, preset);
}

}  // namespace lacrima::player
