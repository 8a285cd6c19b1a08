#pragma once
// Which paths are Lacrima projects: the one rule the editor, the player and lacrima-fap share,
// so a file one of them saves is a project to the others. Projects are JSON inside; .lacrima
// is their own extension (the desktop associates it with Lacrima, where .json is everyone's),
// and .json is still read, as every project before .lacrima was saved so.
#include <string_view>

namespace lacrima::inline common {

// The extension the editor gives new projects.
inline constexpr std::string_view kProjectExtension = ".lacrima";

// True when `path` ends in .lacrima or .json, in any case; anything else is a FAP file.
bool isProjectPath(std::string_view path);

}  // namespace lacrima::inline common
