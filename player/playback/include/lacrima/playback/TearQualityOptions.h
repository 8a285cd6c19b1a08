#pragma once
// What each tear quality level (common's TearQuality.h) means to the simulation: the sub-step
// factor, pressure solver, surface tension and neighbour structure, chosen from the measured
// accuracy against cost of `lacrima-bench tears-sweep` (docs/decisions/0014). Balanced is the
// simulation's defaults, so a project that never chose simulates exactly as before.
#include <lacrima/common/TearQuality.h>
#include <lacrima/tears/SimulationOptions.h>

#include <string_view>

namespace lacrima::playback {

struct TearQualityLevel {
  TearQuality level;
  // Scales the sub-step safety factors (lambdaCfl, lambdaAcceleration): above 1 fewer, longer
  // sub-steps; below 1 more, shorter ones. The sweep's "sub-step factor" column.
  double substepFactor;
  std::string_view solver;  // keys of the method registries (tears/TearMethods.h)
  std::string_view tension;
  std::string_view neighbours;
  std::string_view label;    // for the apps' combo, e.g. "Balanced"
  std::string_view summary;  // what it trades, with the sweep's figures (tooltips)
};

// Preview, Balanced, Reference.
const TearQualityLevel& tearQualityLevel(TearQuality level);

// The options a simulation runs with for `quality`: the level's, with the advanced choices
// that are set replacing the level's own. Everything else keeps SimulationOptions' defaults.
// Throws std::invalid_argument naming the known keys for a choice no registry holds.
tears::SimulationOptions simulationOptions(const TearQualitySettings& quality);

// The keys a project may name for each advanced choice: the registries' (for
// ProjectDocument::load in the apps, so an unknown key is refused as the file is read).
TearMethodKeys tearMethodKeys();

}  // namespace lacrima::playback
