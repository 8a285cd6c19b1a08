#include <lacrima/scene/CameraPreset.h>
#include <lacrima/scene/OverlayMasks.h>

#include <Eigen/Geometry>

#include <array>
#include <string>
#include <utility>

namespace lacrima::scene {
namespace {

constexpr std::array kNames{
    std::pair{CameraPreset::Framing, std::string_view("framing")},
    std::pair{CameraPreset::Front, std::string_view("front")},
    std::pair{CameraPreset::ThreeQuarter, std::string_view("three-quarter")},
    std::pair{CameraPreset::Profile, std::string_view("profile")},
    std::pair{CameraPreset::CloseLeft, std::string_view("close-left")},
    std::pair{CameraPreset::CloseRight, std::string_view("close-right")},
};

Eigen::AlignedBox3d boundsOf(const HeadMesh& head) {
  return {head.boundsMin().cast<double>(), head.boundsMax().cast<double>()};
}

// The cheek below one eye: where the tear of that eye runs. side is +1 for the face's left.
OrbitView closeUp(const HeadMesh& head, const OrbitView& framing, double side) {
  const Eigen::AlignedBox3d all = boundsOf(head);
  const double height = all.sizes().y();
  Eigen::Vector3d eye(all.center().x() + side * 0.25 * all.sizes().x(), framing.target.y(),
                      framing.target.z());
  if (const auto sphere = eyeSphere(head, side > 0 ? "eye_l" : "eye_r"))
    eye = sphere->centre.cast<double>();
  OrbitView view = framing;
  // 0.10 head heights below the eye's centre: the lower lid's edge and the cheek beneath it.
  view.target = Eigen::Vector3d(eye.x(), eye.y() - 0.10 * height, eye.z());
  view.yawDegrees = side * 25;
  view.pitchDegrees = 6;
  view.distance = framing.distance * 0.28;
  return view;
}

}  // namespace

std::string_view toString(CameraPreset preset) {
  for (const auto& [value, name] : kNames)
    if (value == preset) return name;
  return "framing";
}

std::optional<CameraPreset> parseCameraPreset(std::string_view name) {
  for (const auto& [value, known] : kNames)
    if (known == name) return value;
  return std::nullopt;
}

std::string_view cameraPresetNames() {
  static const std::string names = [] {
    std::string joined;
    for (const auto& [value, name] : kNames) {
      if (!joined.empty()) joined += ", ";
      joined += name;
    }
    return joined;
  }();
  return names;
}

OrbitView presetView(const HeadMesh& head, CameraPreset preset) {
  OrbitView view = OrbitView::framing(head);
  switch (preset) {
    case CameraPreset::Framing:
      break;
    case CameraPreset::Front:
      view.yawDegrees = 0;
      view.pitchDegrees = 0;
      break;
    case CameraPreset::ThreeQuarter:
      view.yawDegrees = 45;
      view.pitchDegrees = 5;
      break;
    case CameraPreset::Profile:
      // Seen from the side the head's depth runs across the image: centre it.
      view.target.z() = boundsOf(head).center().z();
      view.yawDegrees = 90;
      view.pitchDegrees = 0;
      break;
    case CameraPreset::CloseLeft:
      view = closeUp(head, view, +1);
      break;
    case CameraPreset::CloseRight:
      view = closeUp(head, view, -1);
      break;
  }
  return view;
}

}  // namespace lacrima::scene
