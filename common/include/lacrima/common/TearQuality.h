#pragma once
// How accurately, and so how expensively, the tears are simulated: a quality level and, for
// the advanced user, explicit choices of pressure solver, surface-tension model and neighbour
// structure that replace the level's. Names and values only: the choices are keys of the
// simulation's method registries (player/tears, TearMethods.h), which common cannot see; the
// simulation options each level stands for are mapped in player/playback
// (TearQualityOptions.h). The levels and the figures behind them: docs/decisions/0014.
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lacrima::inline common {

// Preview: fewer, longer sub-steps (faster, drops wander further from the reference).
// Balanced: the simulation's defaults.
// Reference: shorter sub-steps (slower, closest to a fine reference run).
enum class TearQuality { Preview, Balanced, Reference };

struct TearQualitySettings {
  TearQuality level = TearQuality::Balanced;
  // Advanced: registry keys ("dfsph", "akinci", "octree"); nullopt keeps what the level uses.
  std::optional<std::string> solver;
  std::optional<std::string> tension;
  std::optional<std::string> neighbours;

  bool operator==(const TearQualitySettings&) const = default;
};

// The keys a reader accepts for each advanced choice: what the simulation's registries hold
// (playback::tearMethodKeys()). A reader given none accepts any well-formed key, for the tools
// that never simulate (lacrima-fap) and keep the choice as it was written.
struct TearMethodKeys {
  std::vector<std::string> solvers, tensions, neighbours;
};

// The names used in project files and on the command line, in enum order.
inline constexpr std::array<std::string_view, 3> kTearQualityNames{"preview", "balanced",
                                                                   "reference"};

std::string_view toString(TearQuality level);

// nullopt for a name not in the lists above (case-sensitive, as the files are).
std::optional<TearQuality> parseTearQuality(std::string_view name);

}  // namespace lacrima::inline common
