#include <lacrima/scene/CameraPreset.h>

#include <Eigen/Geometry>

#include <array>
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

Eigen::AlignedBox3d boundsOf(const HeadMesh& head, int first, int count) {
  Eigen::AlignedBox3d box;
  for (int v = first; v < first + count; ++v) box.extend(head.positions.col(v).cast<double>());
  return box;
}

// The cheek below one eye: where the tear of that eye runs. side is +1 for the face's left.
OrbitView closeUp(const HeadMesh& head, const OrbitView& framing, double side) {
  const Eigen::AlignedBox3d all = boundsOf(head, 0, head.vertexCount());
  const double height = all.sizes().y();
  Eigen::Vector3d eye(all.center().x() + side * 0.25 * all.sizes().x(), framing.target.y(),
                      framing.target.z());
  if (const HeadSubmesh* sub = head.findSubmesh(side > 0 ? "eye_l" : "eye_r");
      sub && sub->vertexCount > 0)
    eye = boundsOf(head, sub->firstVertex, sub->vertexCount).center();
  OrbitView view = framing;
  // 0.12 head heights below the eye's centre: the lower lid's edge and the cheek beneath it.
  view.target = Eigen::Vector3d(eye.x(), eye.y() - 0.12 * height, eye.z());
  view.yawDegrees = side * 25;
  view.pitchDegrees = 6;
  view.distance = framing.distance * 0.26;
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
  return "framing, front, three-quarter, profile, close-left, close-right";
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
      view.target.z() = boundsOf(head, 0, head.vertexCount()).center().z();
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
