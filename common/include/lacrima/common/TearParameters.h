#pragma once
// The tear simulation's tunable parameters: names, defaults and valid ranges, shared by the
// project document, the player's parameter panel and the simulation's JSON loader.
// Defaults are the settings of the 2009 system (in its units; the simulation scales
// lengths to the head).
#include <map>
#include <span>
#include <string>
#include <string_view>

namespace lacrima::inline common {

// One value per parameter of the table, in the 2009 units: adding a parameter is one field here
// and one row of the table, which points at the field (the simulation's TearSettings builds on
// this, and reads and writes its values by name through the table alone).
struct TearParameterSet {
  double pressure = 0, viscosity = 0, tension = 0, adhesion = 0, friction = 0, gravity = 0,
         kernel = 0, nodeSize = 0, cubeSize = 0, iso = 0;
};

struct TearParameterInfo {
  std::string_view name;  // JSON key, e.g. "adhesion"
  double TearParameterSet::*field;
  double defaultValue;
  double minValue, maxValue;  // inclusive
  std::string_view description;
};

// pressure viscosity tension adhesion friction gravity kernel node_size cube_size iso
std::span<const TearParameterInfo> tearParameterTable();
const TearParameterInfo* findTearParameter(std::string_view name);

// Values by name; only names from the table, each within its range.
using TearParameterValues = std::map<std::string, double, std::less<>>;

// Why `value` cannot be parameter `name` ("unknown parameter 'x'; expected one of: ...",
// "20000 is outside [0, 10000]"; NaN and infinities are outside too), or "" when it can.
std::string tearParameterProblem(std::string_view name, double value);

// Throws std::invalid_argument with the problem, prefixed "<name>: " for a value out of range.
void validateTearParameter(std::string_view name, double value);

class JsonValue;
// An object of name: number, each valid. Throws FileError at the first member that is not, as
// "file:line:column: path.name: <tearParameterProblem>" (JsonValue.h).
TearParameterValues readTearParameters(const JsonValue& object);

}  // namespace lacrima::inline common
