#include <lacrima/scene/CameraPreset.h>
#include <lacrima/scene/OverlayMasks.h>

#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <optional>
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

// What the views are measured from: the reset view, the head's box and the eyes the close
// views look under (nullopt: a quarter of the box's width to that side).
struct HeadMeasure {
  OrbitView framing;
  Eigen::AlignedBox3d box;
  std::optional<Eigen::Vector3d> eyeLeft, eyeRight;
};

// The cheek below one eye: where the tear of that eye runs. side is +1 for the face's left.
OrbitView closeUp(const HeadMeasure& head, double side) {
  const OrbitView& framing = head.framing;
  const double height = head.box.sizes().y();
  Eigen::Vector3d eye(head.box.center().x() + side * 0.25 * head.box.sizes().x(),
                      framing.target.y(), framing.target.z());
  if (const auto& known = side > 0 ? head.eyeLeft : head.eyeRight) eye = *known;
  OrbitView view = framing;
  // 0.10 head heights below the eye's centre: the lower lid's edge and the cheek beneath it.
  view.target = Eigen::Vector3d(eye.x(), eye.y() - 0.10 * height, eye.z());
  view.yawDegrees = side * 25;
  view.pitchDegrees = 6;
  view.distance = framing.distance * 0.28;
  return view;
}

OrbitView presetFrom(const HeadMeasure& head, CameraPreset preset) {
  OrbitView view = head.framing;
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
      view.target.z() = head.box.center().z();
      view.yawDegrees = 90;
      view.pitchDegrees = 0;
      break;
    case CameraPreset::CloseLeft:
      view = closeUp(head, +1);
      break;
    case CameraPreset::CloseRight:
      view = closeUp(head, -1);
      break;
  }
  return view;
}

std::optional<Eigen::Vector3d> eyeSphereCentre(const HeadMesh& head, const char* submesh) {
  if (const auto sphere = eyeSphere(head, submesh)) return sphere->centre.cast<double>();
  return std::nullopt;
}

// Landmarks a face can be framed by: finite, a positive ES0, the left eye at +x of the right
// one and the two level within an ES0.
bool usable(const FaceLandmarks& face) {
  const Eigen::Vector3d apart = face.eyeLeft - face.eyeRight;
  return face.eyeLeft.allFinite() && face.eyeRight.allFinite() && face.chin.allFinite() &&
         std::isfinite(face.eyeSeparation) && face.eyeSeparation > 0 && apart.x() > 0 &&
         std::abs(apart.y()) < face.eyeSeparation;
}

// The head proper: the box of the vertices above the neck cut. A head with nothing below the
// cut keeps exactly its whole box (the same floats, extended in the same order).
Eigen::AlignedBox3d headProperBox(const HeadMesh& head, const FaceLandmarks& face) {
  const double cut = face.chin.y() - kNeckCutBelowChin * face.eyeSeparation;
  Eigen::AlignedBox3d box;
  for (int v = 0; v < head.vertexCount(); ++v) {
    const Eigen::Vector3d p = head.positions.col(v).cast<double>();
    if (p.y() >= cut) box.extend(p);
  }
  return box;
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
  return presetFrom({OrbitView::framing(head), boundsOf(head), eyeSphereCentre(head, "eye_l"),
                     eyeSphereCentre(head, "eye_r")},
                    preset);
}

OrbitView presetView(const HeadMesh& head, CameraPreset preset, const FaceLandmarks& face) {
  if (!usable(face)) return presetView(head, preset);
  const Eigen::AlignedBox3d box = headProperBox(head, face);
  if (box.isEmpty() || !box.sizes().allFinite() || !(box.sizes().y() > 0))
    return presetView(head, preset);
  HeadMeasure measure{OrbitView{}, box, face.eyeLeft, face.eyeRight};
  if (const auto named = namedEyeCentres(head)) {
    // The mesh names its eyes (the default head): frame by their boxes and look under their
    // spheres, as the mesh-only views do, so those views stay the same to the bit.
    measure.framing = OrbitView::framingFace(named->first, named->second, box);
    measure.eyeLeft = eyeSphereCentre(head, "eye_l");
    measure.eyeRight = eyeSphereCentre(head, "eye_r");
  } else {
    measure.framing = OrbitView::framingFace(face.eyeLeft, face.eyeRight, box);
  }
  return presetFrom(measure, preset);
}

}  // namespace lacrima::scene
