#include "TearMethodOptions.h"

#include <array>
#include <stdexcept>
#include <utility>

namespace lacrima::bench {

namespace {

using tears::MethodChoice;
using tears::MethodFamily;
using tears::MethodInfo;
using tears::MethodParameter;

struct FamilyOption {
  MethodFamily family;
  const char* name;  // the option's name
  MethodChoice tears::SimulationOptions::*choice;
};

constexpr std::array kFamilies{
    FamilyOption{MethodFamily::PressureSolver, "solver", &tears::SimulationOptions::pressureSolver},
    FamilyOption{MethodFamily::SurfaceTension, "tension",
                 &tears::SimulationOptions::surfaceTension},
    FamilyOption{MethodFamily::NeighbourStructure, "neighbours",
                 &tears::SimulationOptions::neighbours},
};

QString fromUtf8(const std::string& text) { return QString::fromStdString(text); }

QString familyHelp(const FamilyOption& family, const std::string& defaultKey) {
  QString help = fromUtf8(std::string(tears::familyName(family.family)));
  help[0] = help[0].toUpper();
  help += ":";
  for (const MethodInfo& method : tears::registeredMethods(family.family))
    help += " " + fromUtf8(method.key) + " (" + fromUtf8(method.summary) + ");";
  help += " default " + fromUtf8(defaultKey) + ".";
  return help;
}

void addParameterOption(BenchCommandLine& line, const FamilyOption& family,
                        const MethodInfo& method, const MethodParameter& parameter,
                        tears::SimulationOptions& options) {
  const QString help = fromUtf8(method.label + ": " + parameter.description) + " (default " +
                       QString::number(parameter.defaultValue) + "; from " +
                       QString::number(parameter.minimum) + " to " +
                       QString::number(parameter.maximum) + ").";
  line.option(fromUtf8(method.key + "-" + parameter.key), parameter.wholeNumber ? "N" : "V", help,
              [&family, &options, method, parameter](const QString& text) -> std::string {
                MethodChoice& choice = options.*family.choice;
                if (choice.key != method.key)
                  return "applies to --" + std::string(family.name) + " " + method.key +
                         " only (the " + std::string(tears::familyName(family.family)) +
                         " chosen is " + choice.key + ")";
                bool ok = false;
                const double value = text.toDouble(&ok);
                if (!ok) return "expected a number, not '" + text.toStdString() + "'";
                MethodChoice tried = choice;
                tried.parameters[parameter.key] = value;
                try {
                  tears::checkMethodChoice(family.family, tried);
                } catch (const std::invalid_argument& e) {
                  return e.what();
                }
                choice = std::move(tried);
                return {};
              });
}

}  // namespace

void addTearMethodOptions(BenchCommandLine& line, tears::SimulationOptions& options) {
  // Every choice first: the parameters' readers run after them and check the method chosen.
  for (const FamilyOption& family : kFamilies) {
    line.option(family.name, "KEY", familyHelp(family, (options.*family.choice).key),
                [&family, &options](const QString& text) -> std::string {
                  const MethodChoice choice(text.toStdString());
                  try {
                    tears::checkMethodChoice(family.family, choice);
                  } catch (const std::invalid_argument& e) {
                    return e.what();
                  }
                  options.*family.choice = choice;
                  return {};
                });
  }
  for (const FamilyOption& family : kFamilies)
    for (const MethodInfo& method : tears::registeredMethods(family.family))
      for (const MethodParameter& parameter : method.parameters)
        addParameterOption(line, family, method, parameter, options);
}

std::string describeMethod(MethodFamily family, const MethodChoice& choice) {
  const std::optional<MethodInfo> method = tears::findMethod(family, choice.key);
  if (!method) return choice.key;
  std::string text = method->label;
  if (method->parameters.empty()) return text;
  const tears::MethodValues values(*method, choice);
  for (std::size_t i = 0; i < method->parameters.size(); ++i) {
    const std::string& key = method->parameters[i].key;
    text += (i == 0 ? " (" : ", ") + key + " " + QString::number(values.number(key)).toStdString();
  }
  return text + ")";
}

}  // namespace lacrima::bench
