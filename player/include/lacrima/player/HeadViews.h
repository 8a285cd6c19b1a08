#pragma once
// The named cameras (scene/CameraPreset.h) of a rigged head, measured from its own landmarks:
// the eye centres (the fitted ones, else the pupils 3.5 / 3.6), the chin 2.1 and ES0 of its rig.
// The player's --render and every other caller that has the rig use this, so the views fit any
// head in any unit; scene::presetView(head, preset) alone is the mesh-only fallback.
#include <lacrima/playback/HeadRig.h>
#include <lacrima/scene/CameraPreset.h>

#include <optional>

namespace lacrima::player {

// The rig's landmarks in the head's coordinates (the face frame); nullopt when it lacks an eye
// centre and its pupil point, or the chin.
std::optional<scene::FaceLandmarks> faceLandmarks(const playback::HeadRig& rig);

// scene::presetView with faceLandmarks(rig) when there are any, the mesh alone otherwise.
scene::OrbitView presetView(const playback::HeadRig& rig, scene::CameraPreset preset);

}  // namespace lacrima::player
