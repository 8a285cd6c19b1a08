#pragma once
// The simulation's interchangeable methods, one registry per family: pressure solvers, surface
// tension models and neighbour structures. Each method is a class next to its family's base
// class, declaring its key, label, summary and parameters once (its static info()); the
// family's registration file (PressureSolverRegistration.cpp, SurfaceTensionRegistration.cpp,
// NeighbourStructureRegistration.cpp) lists the methods in the order users see them. Projects,
// the apps' Effects panel, the quality levels, lacrima-bench and its sweep all read the
// registries through this header, so a new method is one class plus one line there
// (docs/ARCHITECTURE.md).
//
// A key is the one vocabulary for a method: a project's "solver", "tension" and "neighbours",
// the bench's --solver, --tension and --neighbours, the sweep's CSV and JSON. A key no registry
// knows is an error naming the keys it does know, never a silent default.
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace lacrima::tears {

enum class MethodFamily { PressureSolver, SurfaceTension, NeighbourStructure };

// "pressure solver", "surface tension", "neighbour structure": for messages.
std::string_view familyName(MethodFamily family);

// A number a method is tuned by, with its default and the range it accepts.
struct MethodParameter {
  std::string key;          // "iterations"; the bench's option is --<method>-<key>
  std::string description;  // one line, for --help and tooltips
  double defaultValue = 0;
  double minimum = 0, maximum = 0;
  bool wholeNumber = false;  // a count, or 0/1 for a switch
};

struct MethodInfo {
  std::string key;      // "wcsph"
  std::string label;    // "WCSPH": combos and printouts
  std::string summary;  // what it is and what it trades, one sentence
  std::vector<MethodParameter> parameters;

  const MethodParameter* parameter(std::string_view parameterKey) const;
};

// A method as the simulation options name it: the key, and those of its parameters that differ
// from the method's defaults.
struct MethodChoice {
  std::string key;
  std::map<std::string, double, std::less<>> parameters;

  MethodChoice() = default;
  // A key alone is a choice with the method's defaults: options.pressureSolver = "dfsph".
  MethodChoice(std::string methodKey) : key(std::move(methodKey)) {}  // NOLINT(implicit)
  MethodChoice(const char* methodKey) : key(methodKey) {}             // NOLINT(implicit)
  bool operator==(const MethodChoice&) const = default;
};

// The values a method runs with: its parameters' defaults, with what the choice sets over them.
class MethodValues {
 public:
  // Throws std::invalid_argument for a parameter the method does not have, or a value outside
  // its range or not whole where it must be.
  MethodValues(const MethodInfo& method, const MethodChoice& choice);

  double number(std::string_view parameterKey) const;
  int wholeNumber(std::string_view parameterKey) const;
  bool flag(std::string_view parameterKey) const { return number(parameterKey) != 0; }

 private:
  std::string method_;
  std::map<std::string, double, std::less<>> values_;
};

// The family's methods in registration order.
std::vector<MethodInfo> registeredMethods(MethodFamily family);
std::vector<std::string> registeredKeys(MethodFamily family);
std::optional<MethodInfo> findMethod(MethodFamily family, std::string_view key);
// "\"wcsph\", \"dfsph\" or \"pbf\"": the known keys, for messages.
std::string knownKeys(MethodFamily family);
// Throws std::invalid_argument for an unknown key ("unknown pressure solver "x"; expected
// ...") or a bad parameter (MethodValues).
void checkMethodChoice(MethodFamily family, const MethodChoice& choice);

}  // namespace lacrima::tears
