// The quality levels (TearQualityOptions.h). Figures: lacrima-bench tears-sweep on the cheek
// sheet, errors in particle radii against a fine reference (docs/performance.md, "Accuracy
// against cost"; docs/decisions/0014).
#include <lacrima/playback/TearQualityOptions.h>

#include <algorithm>
#include <array>
#include <cstddef>

namespace lacrima::playback {

namespace {

// Only the sub-step factor changes between levels. DFSPH is not a more accurate WCSPH (its
// drops run 40-75 radii from the WCSPH reference, decision 0009) and the octree finds the same
// pairs more slowly, so those stay advanced choices rather than levels.
constexpr std::array<TearQualityLevel, 3> kLevels{{
    {TearQuality::Preview, 1.5, "wcsph", "mueller", "grid", "Preview",
     "Longer sub-steps (x1.5): about two thirds of Balanced's sub-steps and time; drops end 2.6 "
     "particle radii from a fine reference instead of 1.6"},
    {TearQuality::Balanced, 1.0, "wcsph", "mueller", "grid", "Balanced",
     "The defaults (WCSPH, sub-step factor x1): drops end 1.6 particle radii from a fine "
     "reference"},
    {TearQuality::Reference, 0.5, "wcsph", "mueller", "grid", "Reference",
     "Shorter sub-steps (x0.5): about twice Balanced's sub-steps, 1.8 times its time; drops end "
     "0.86 particle radii from a fine reference"},
}};

}  // namespace

const TearQualityLevel& tearQualityLevel(TearQuality level) {
  return kLevels.at(static_cast<std::size_t>(level));
}

tears::SimulationOptions simulationOptions(const TearQualitySettings& quality) {
  const TearQualityLevel& level = tearQualityLevel(quality.level);
  tears::SimulationOptions options;
  options.scaleSubsteps(level.substepFactor);  // as the sweep scales them
  options.pressureSolver = quality.solver.value_or(std::string(level.solver));
  options.surfaceTension = quality.tension.value_or(std::string(level.tension));
  options.neighbours = quality.neighbours.value_or(std::string(level.neighbours));
  tears::checkMethodChoice(tears::MethodFamily::PressureSolver, options.pressureSolver);
  tears::checkMethodChoice(tears::MethodFamily::SurfaceTension, options.surfaceTension);
  tears::checkMethodChoice(tears::MethodFamily::NeighbourStructure, options.neighbours);
  return options;
}

TearMethodKeys tearMethodKeys() {
  return {tears::registeredKeys(tears::MethodFamily::PressureSolver),
          tears::registeredKeys(tears::MethodFamily::SurfaceTension),
          tears::registeredKeys(tears::MethodFamily::NeighbourStructure)};
}

}  // namespace lacrima::playback
