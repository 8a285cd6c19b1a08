#include <lacrima/common/JsonValue.h>
#include <lacrima/common/TearParameters.h>

#include <array>
#include <charconv>
#include <stdexcept>

namespace lacrima::inline common {
namespace {

// Defaults are the 2009 settings. Ranges are deliberately wide: the simulation must survive
// (not necessarily look good at) anything the panel or a hand-edited project lets through,
// so the stress cases (sticky, stiff, inviscid, huge or tiny kernels) stay expressible.
// Lower bounds of the lengths and of iso stay above 0 because they divide or size a grid.
constexpr std::array kTable{
    TearParameterInfo{"pressure", &TearParameterSet::pressure, 0.004, 0.0, 10.0,
                      "Stiffness of the SPH equation of state: how hard the fluid pushes back "
                      "when compressed."},
    TearParameterInfo{"viscosity", &TearParameterSet::viscosity, 0.9, 0.0, 100.0,
                      "How strongly neighbouring particles damp their relative velocity "
                      "(0 = inviscid)."},
    TearParameterInfo{"tension", &TearParameterSet::tension, 0.2, 0.0, 100.0,
                      "Surface tension: pull along the colour-field normal that keeps drops "
                      "round and trails thin."},
    TearParameterInfo{"adhesion", &TearParameterSet::adhesion, 20.0, 0.0, 10000.0,
                      "Attraction of particles to the skin, which lets tears cling to the "
                      "cheek instead of dropping."},
    TearParameterInfo{"friction", &TearParameterSet::friction, 3.8, 0.0, 1000.0,
                      "Tangential drag of the skin on particles touching it; slows tears "
                      "rolling down the face."},
    TearParameterInfo{"gravity", &TearParameterSet::gravity, 9.81, 0.0, 100.0,
                      "Downward acceleration of every particle; 9.81 is Earth's in the "
                      "2009 units."},
    TearParameterInfo{"kernel", &TearParameterSet::kernel, 0.5, 0.01, 50.0,
                      "SPH smoothing length h: the radius within which particles interact."},
    TearParameterInfo{"node_size", &TearParameterSet::nodeSize, 0.5, 0.005, 50.0,
                      "Edge of an octree leaf used for neighbour search; matches the kernel "
                      "by default."},
    TearParameterInfo{"cube_size", &TearParameterSet::cubeSize, 0.25, 0.005, 50.0,
                      "Edge of a marching-cubes cell of the tear surface; half a node by "
                      "default."},
    TearParameterInfo{"iso", &TearParameterSet::iso, 0.5, 1e-6, 100.0,
                      "Colour-field level at which the tear surface is extracted; must be "
                      "positive."},
};

std::string formatNumber(double value) {
  std::array<char, 32> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  return std::string(buffer.data(), result.ptr);
}

std::string knownNames() {
  std::string names;
  for (const auto& info : kTable) {
    if (!names.empty()) names += ", ";
    names += info.name;
  }
  return names;
}

}  // namespace

std::span<const TearParameterInfo> tearParameterTable() { return kTable; }

const TearParameterInfo* findTearParameter(std::string_view name) {
  for (const auto& info : kTable) {
    if (info.name == name) return &info;
  }
  return nullptr;
}

std::string tearParameterProblem(std::string_view name, double value) {
  const TearParameterInfo* info = findTearParameter(name);
  if (!info)
    return "unknown parameter '" + std::string(name) + "'; expected one of: " + knownNames();
  // Written so that NaN, which compares false with everything, fails too.
  if (value >= info->minValue && value <= info->maxValue) return {};
  return formatNumber(value) + " is outside [" + formatNumber(info->minValue) + ", " +
         formatNumber(info->maxValue) + "]";
}

void validateTearParameter(std::string_view name, double value) {
  const std::string problem = tearParameterProblem(name, value);
  if (problem.empty()) return;
  throw std::invalid_argument(findTearParameter(name) ? std::string(name) + ": " + problem
                                                      : problem);
}

TearParameterValues readTearParameters(const JsonValue& object) {
  TearParameterValues values;
  for (const JsonValue& parameter : object.members()) {
    if (!parameter.isNumber()) parameter.fail("expected a number, got " + parameter.describe());
    const std::string problem = tearParameterProblem(parameter.name(), parameter.number());
    if (!problem.empty()) parameter.fail(problem);
    values[parameter.name()] = parameter.number();
  }
  return values;
}

}  // namespace lacrima::inline common
