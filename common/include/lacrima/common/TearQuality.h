#pragma once
// How accurately, and so how expensively, the tears are simulated: a quality level and, for
// the advanced user, explicit choices of pressure solver, surface-tension model and neighbour
// structure that replace the level's. Names and values only; the simulation options each level
// stands for are mapped in player/playback (TearQualityOptions.h), so common stays free of the
// simulation's headers. The levels and the figures behind them: docs/decisions/0014.
#include <array>
#include <optional>
#include <string_view>

namespace lacrima::inline common {

// Preview: fewer, longer sub-steps (faster, drops wander further from the reference).
// Balanced: the defaults every project had before the choice existed.
// Reference: shorter sub-steps (slower, closest to a fine reference run).
enum class TearQuality { Preview, Balanced, Reference };
// Weakly compressible SPH, divergence-free SPH or position-based fluids.
enum class TearSolver { Wcsph, Dfsph, Pbf };
enum class TearTension { Mueller, Akinci };  // colour-field curvature, or cohesion + curvature
enum class TearNeighbours { Grid, Octree };  // Verlet lists on a grid, or the 2009 octree

struct TearQualitySettings {
  TearQuality level = TearQuality::Balanced;
  // Advanced: nullopt keeps what the level uses.
  std::optional<TearSolver> solver;
  std::optional<TearTension> tension;
  std::optional<TearNeighbours> neighbours;

  bool operator==(const TearQualitySettings&) const = default;
};

// The names used in project files and on the command line, in enum order:
// "preview" "balanced" "reference"; "wcsph" "dfsph" "pbf"; "mueller" "akinci"; "grid" "octree".
inline constexpr std::array<std::string_view, 3> kTearQualityNames{"preview", "balanced",
                                                                   "reference"};
inline constexpr std::array<std::string_view, 3> kTearSolverNames{"wcsph", "dfsph", "pbf"};
inline constexpr std::array<std::string_view, 2> kTearTensionNames{"mueller", "akinci"};
inline constexpr std::array<std::string_view, 2> kTearNeighbourNames{"grid", "octree"};

std::string_view toString(TearQuality level);
std::string_view toString(TearSolver solver);
std::string_view toString(TearTension tension);
std::string_view toString(TearNeighbours neighbours);

// nullopt for a name not in the lists above (case-sensitive, as the files are).
std::optional<TearQuality> parseTearQuality(std::string_view name);

}  // namespace lacrima::inline common
