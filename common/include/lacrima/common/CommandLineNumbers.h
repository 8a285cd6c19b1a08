#pragma once
// Numbers the applications read from their command lines (lacrima-editor --time, --focus,
// --warm-up; lacrima-player --at). The whole value must be the number, within its bounds;
// otherwise `error` gets the line the application prints after its name, naming the option and
// what it expects, and the application exits with status 2 (wrong usage).
#include <optional>
#include <string>
#include <string_view>

namespace lacrima::inline common {

// `what` names the unit in the message: "--time: expected seconds from 0 to 86400, not 'abc'".
std::optional<double> readNumberOption(std::string_view option, std::string_view what,
                                       std::string_view text, double low, double high,
                                       std::string& error);
std::optional<int> readWholeNumberOption(std::string_view option, std::string_view what,
                                         std::string_view text, int low, int high,
                                         std::string& error);

}  // namespace lacrima::inline common
