#pragma once
// Writer for the portable .fap profile (FAP_FILE_FORMAT §8):
//   2.1 <name-without-spaces> <integer fps> <nframes>
//   68 mask tokens (70 when a tear channel is non-zero somewhere and not strict), m1 = m2 = 0
//   <frame> <integer value per masked FAP, ascending>      frames 0..n-1, in order
// Single spaces, LF, newline at end. Every channel that is animated or non-zero in any frame is
// masked in every frame (with its 0s written), because readers disagree on masked-off FAPs.
#include <lacrima/common/Diagnostics.h>
#include <lacrima/common/FapAnimation.h>

#include <string>

namespace lacrima::inline common {

struct FapWriteOptions {
  // Always 68 mask tokens, no tear channels: for players that know only the standard.
  bool strict = false;
};

class FapWriter {
 public:
  // The file's text. Values are rounded to integers; a non-integer fps is rounded (warned).
  // FAP 1/2 are never written (portable rule); if they carry data a warning says so.
  static std::string toText(const FapAnimation& animation, const FapWriteOptions& options = {},
                            Warnings* warnings = nullptr);

  // Atomic save: writes a temporary file beside `path`, then renames it over `path`.
  // On failure throws FileError and leaves any existing file untouched.
  static void save(const FapAnimation& animation, const std::string& path,
                   const FapWriteOptions& options = {}, Warnings* warnings = nullptr);
};

}  // namespace lacrima::inline common
