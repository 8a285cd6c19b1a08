#pragma once
// Tolerant reader for the plain-text .fap format (docs/fap.md, "FAP files").
//
// Accepts: version 2.0/2.1 (others warn), integer or decimal fps, names with spaces (warns),
// '#' comment lines and blank lines anywhere, tabs, CRLF, decimal values, masks of 68 or 70
// tokens, FAP 1/2 in the grouped (4/6 tokens) or scalar (1 token) dialect, detected from the
// value line's token count. Masked-off FAPs are 0 in that frame. Missing frames are filled by
// linear interpolation between present neighbours (held before the first and after the last),
// frame numbers >= nframes extend the animation; both warn.
//
// Rejects with FileError("file:line:column: what was expected"): empty or binary input,
// bad header, mask tokens other than 0/1, wrong token counts, non-numeric tokens, a mask line
// with no value line, lines over kMaxLineLength, tear counts that are not whole numbers in
// [0, kMaxTearParticles]. Memory is bounded by the input's size, never by numbers in it.
#include <lacrima/common/Diagnostics.h>
#include <lacrima/common/FapAnimation.h>
#include <lacrima/common/FapTextParser.h>

#include <iosfwd>
#include <string>
#include <string_view>

namespace lacrima::inline common {

struct FapReadResult {
  FapAnimation animation;
  int headerFrameCount = 0;  // nframes as written in the header
  Warnings warnings;
};

class FapReader {
 public:
  // Longest physical line accepted: the text parser's, the same for files and streams.
  static constexpr std::size_t kMaxLineLength = FapTextParser::kMaxLineLength;
  // Highest frame count gaps may expand to, beyond the frames actually present: keeps a
  // two-line file that names frame 2'000'000'000 from allocating gigabytes.
  static constexpr int kMaxFilledFrames = 100000;

  // Reads a file; `displayName` defaults to the path and is used in messages.
  static FapReadResult readFile(const std::string& path);

  // Parses text already in memory (tests, stdin). `displayName` appears in messages.
  static FapReadResult parse(std::string_view text, const std::string& displayName);
};

}  // namespace lacrima::inline common
