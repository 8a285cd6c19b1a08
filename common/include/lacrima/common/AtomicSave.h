#pragma once
#include <string>
#include <string_view>

namespace lacrima::inline common {

// Writes `bytes` to a temporary file in the target's folder, flushes it, then renames it over
// `path`, so a crash or a full disk never leaves a half-written file: either the old file or
// the new one is there. Throws FileError naming `path` and the system's reason on failure.
void saveAtomically(const std::string& path, std::string_view bytes);

}  // namespace lacrima::inline common
