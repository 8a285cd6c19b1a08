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
  double pressure = 0, viscosity = 0, tension = 0, adhesion = 0, friction = 0, gravity = 0, kernel = 0, nodeSize = 0,
         cubeSize = 0, iso = 0;
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

// Throws std::invalid_argument("<name>: <why>; expected ...") for an unknown name or a value
// outside its range (NaN and infinities included).
void validateTearParameter(std::string_view name, double value);

}  // namespace lacrima::common
