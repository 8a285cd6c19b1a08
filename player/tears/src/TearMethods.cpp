// The public face of the method registries (TearMethods.h): each family's registry is defined
// in its registration file.
#include "NeighbourStructure.h"
#include "PressureSolver.h"
#include "SurfaceTension.h"

#include <lacrima/tears/TearMethods.h>

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace lacrima::tears {

namespace {

// Calls `use` with the family's registry.
template <typename Use>
decltype(auto) withRegistry(MethodFamily family, Use&& use) {
  switch (family) {
    case MethodFamily::PressureSolver:
      return use(pressureSolverRegistry());
    case MethodFamily::SurfaceTension:
      return use(surfaceTensionRegistry());
    case MethodFamily::NeighbourStructure:
      break;
  }
  return use(neighbourStructureRegistry());
}

std::string formatValue(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

}  // namespace

std::string_view familyName(MethodFamily family) {
  switch (family) {
    case MethodFamily::PressureSolver:
      return "pressure solver";
    case MethodFamily::SurfaceTension:
      return "surface tension";
    case MethodFamily::NeighbourStructure:
      break;
  }
  return "neighbour structure";
}

const MethodParameter* MethodInfo::parameter(std::string_view parameterKey) const {
  for (const MethodParameter& p : parameters)
    if (p.key == parameterKey) return &p;
  return nullptr;
}

MethodValues::MethodValues(const MethodInfo& method, const MethodChoice& choice)
    : method_(method.key) {
  for (const MethodParameter& p : method.parameters) values_[p.key] = p.defaultValue;
  for (const auto& [key, value] : choice.parameters) {
    const MethodParameter* p = method.parameter(key);
    if (!p) {
      std::string known;
      for (const MethodParameter& q : method.parameters)
        known += (known.empty() ? "" : ", ") + q.key;
      throw std::invalid_argument(method.key + " has no parameter \"" + key + "\"" +
                                  (known.empty() ? "" : "; it has " + known));
    }
    if (!(value >= p->minimum && value <= p->maximum) ||
        (p->wholeNumber && value != std::floor(value)))
      throw std::invalid_argument(method.key + " " + key + ": expected " +
                                  (p->wholeNumber ? "a whole number" : "a number") + " in [" +
                                  formatValue(p->minimum) + ", " + formatValue(p->maximum) +
                                  "], got " + formatValue(value));
    values_[key] = value;
  }
}

double MethodValues::number(std::string_view parameterKey) const {
  const auto found = values_.find(parameterKey);
  if (found == values_.end())
    throw std::logic_error(method_ + " declares no parameter \"" + std::string(parameterKey) +
                           "\"");
  return found->second;
}

int MethodValues::wholeNumber(std::string_view parameterKey) const {
  return static_cast<int>(number(parameterKey));
}

std::vector<MethodInfo> registeredMethods(MethodFamily family) {
  return withRegistry(family, [](const auto& registry) { return registry.infos(); });
}

std::vector<std::string> registeredKeys(MethodFamily family) {
  std::vector<std::string> keys;
  for (const MethodInfo& method : registeredMethods(family)) keys.push_back(method.key);
  return keys;
}

std::optional<MethodInfo> findMethod(MethodFamily family, std::string_view key) {
  return withRegistry(family, [key](const auto& registry) -> std::optional<MethodInfo> {
    if (const auto* entry = registry.find(key)) return entry->info;
    return std::nullopt;
  });
}

std::string knownKeys(MethodFamily family) {
  const std::vector<std::string> keys = registeredKeys(family);
  std::string text;
  for (std::size_t i = 0; i < keys.size(); ++i)
    text += (i == 0 ? "\"" : i + 1 == keys.size() ? " or \"" : ", \"") + keys[i] + '"';
  return text;
}

void checkMethodChoice(MethodFamily family, const MethodChoice& choice) {
  withRegistry(family, [&choice](const auto& registry) {
    const auto* entry = registry.find(choice.key);
    if (!entry) throw std::invalid_argument(registry.unknownMessage(choice.key));
    MethodValues(entry->info, choice);
  });
}

}  // namespace lacrima::tears
