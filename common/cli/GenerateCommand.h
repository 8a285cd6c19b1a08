#pragma once
// lacrima-fap generate: a take of the crying generator (docs/mood.md) written as a .fap file or
// a project.
#include <cstdint>
#include <optional>
#include <string>

#include <lacrima/common/mood/Moods.h>

namespace lacrima {

struct GenerateRequest {
  std::optional<MoodLevels> moods;    // --mood, constant
  std::optional<std::string> script;  // --script moods.json
  double seconds = 0;
  std::uint64_t seed = 1;
  double fps = 22;
  bool strict = false;
  std::string output;
};

// Writes the take atomically; throws FileError or std::invalid_argument (with a message that
// names the file, line and what was expected) on bad input or a failed write. Returns the line
// printed to stderr on success.
std::string generate(const GenerateRequest& request);

}  // namespace lacrima
