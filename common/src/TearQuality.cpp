// TearQuality (TearQuality.h): the names of the levels and of the advanced choices.
#include <lacrima/common/TearQuality.h>

#include <cstddef>

namespace lacrima::inline common {

namespace {

template <typename Enum, std::size_t N>
std::string_view nameOf(Enum value, const std::array<std::string_view, N>& names) {
  return names.at(static_cast<std::size_t>(value));
}

}  // namespace

std::string_view toString(TearQuality level) { return nameOf(level, kTearQualityNames); }
std::string_view toString(TearSolver solver) { return nameOf(solver, kTearSolverNames); }
std::string_view toString(TearTension tension) { return nameOf(tension, kTearTensionNames); }
std::string_view toString(TearNeighbours neighbours) {
  return nameOf(neighbours, kTearNeighbourNames);
}

std::optional<TearQuality> parseTearQuality(std::string_view name) {
  for (std::size_t i = 0; i < kTearQualityNames.size(); ++i)
    if (kTearQualityNames[i] == name) return static_cast<TearQuality>(i);
  return std::nullopt;
}

}  // namespace lacrima::inline common
