#pragma once
// The texture-blend weights of a frame (FrameView.h, OverlayWeights), from the scene settings,
// how far through the animation the frame is, and the tears:
//   redness   Animation: the 2009 ramp, progress clamped to [0, 1] (eyes redden as the
//             animation goes on and stay red at its end);
//             Tears: the mean over both eyes of the simulation's wet-skin measure
//             1 - exp(-V / V_ref) (TearSimulation::wetness), where V is the water the tears have
//             left on the skin so far, so redness follows the crying actually done and never
//             falls back while the animation plays on;
//   wetEyes   per eye, min(1, particles at that eye / reference count): the eye looks watery
//             while tears are present and dries as soon as they are gone;
//   blush     the redness, when the scene asks for a blush; else 0.
// Colours the animation keys (a project's colour curves, KeyedColours) replace the computed
// redness, and the blush when the scene asks for one (docs/decisions/0019).
// With texture blending off every weight is 0, so a renderer that ignores the flag still draws
// the plain skin.
#include <lacrima/common/ProjectDocument.h>
#include <lacrima/playback/FrameView.h>

namespace lacrima::tears {
class TearSimulation;
}

namespace lacrima::playback {

// `simulation` may be null (no tears have been simulated yet).
OverlayWeights overlayWeights(const SceneSettings& scene, double progress,
                              const tears::TearSimulation* simulation,
                              const KeyedColours& keyed = {});

}  // namespace lacrima::playback
