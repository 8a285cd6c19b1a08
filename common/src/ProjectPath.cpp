// The project file rule (ProjectPath.h).
#include <lacrima/common/ProjectPath.h>

#include <algorithm>
#include <cctype>

namespace lacrima::inline common {

namespace {

bool endsWithIgnoringCase(std::string_view text, std::string_view suffix) {
  return text.size() >= suffix.size() &&
         std::equal(suffix.begin(), suffix.end(), text.end() - static_cast<long>(suffix.size()),
                    [](char a, char b) {
                      return std::tolower(static_cast<unsigned char>(a)) ==
                             std::tolower(static_cast<unsigned char>(b));
                    });
}

}  // namespace

bool isProjectPath(std::string_view path) {
  return endsWithIgnoringCase(path, kProjectExtension) || endsWithIgnoringCase(path, ".json");
}

}  // namespace lacrima::inline common
