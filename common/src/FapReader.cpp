#include <lacrima/common/FapReader.h>
#include <lacrima/common/FapTextParser.h>

#include "FapFrameAssembler.h"
#include "FapLineSource.h"

#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>

namespace lacrima::inline common {

namespace {

using detail::FrameAssembler;
using detail::LineSource;

// The shortest possible frame: 68 one-character mask tokens with blanks, then "0\n". Bounds
// the first allocation by the input's size whatever nframes claims.
constexpr std::size_t kMinBytesPerFrame = 137;
constexpr const char* kHeaderForm = "'<version> <name> <fps> <nframes>'";

struct FileCloser {
  void operator()(std::FILE* file) const { std::fclose(file); }
};

// Feeds a file's lines to the text parser and its frames to the assembler.
FapReadResult readLines(LineSource& lines, const std::string& displayName, std::size_t inputSize) {
  FapTextParser parser(displayName, FapTextParser::Header::Required);
  FrameAssembler assembler(displayName, FapReader::kMaxFilledFrames);
  FapReadResult result;
  ChannelMask animated;
  std::string_view line;
  while (lines.next(line)) {
    switch (parser.feed(line, lines.lineNumber())) {
      case FapTextParser::Event::None:
      case FapTextParser::Event::Mood:  // a file's parser refuses mood lines
        break;
      case FapTextParser::Event::Header: {
        const FapTextHeader& header = parser.header();
        const std::size_t fitsInInput = inputSize / kMinBytesPerFrame + 1;
        assembler.setHeader(header.frameCount, header.line, header.frameCountColumn,
                            std::min(static_cast<std::size_t>(header.frameCount), fitsInInput));
        break;
      }
      case FapTextParser::Event::Frame: {
        const FapTextFrame& frame = parser.frame();
        assembler.add(frame.number, frame.line, frame.column) = frame.values;
        if (frame.highLevel) assembler.highLevel() = *frame.highLevel;
        animated |= frame.mask;
        break;
      }
    }
  }
  if (!parser.sawHeader()) {
    throw FileError(
        {displayName, 0, 0},
        std::string(lines.sawInput() ? "no header: the file holds only blank lines and comments"
                                     : "empty file") +
            "; expected the header " + kHeaderForm);
  }
  if (parser.pendingMaskLine() != 0) {
    throw FileError({displayName, parser.pendingMaskLine(), 0},
                    "the file ends after a mask line: expected its value line "
                    "'<frame> <values>'");
  }
  const FapTextHeader& header = parser.header();
  FapAnimation& animation = result.animation;
  animation.version = header.version;
  animation.name = header.name;
  animation.fps = header.fps;
  animation.animated = animated;
  result.headerFrameCount = header.frameCount;
  Warnings warnings = std::move(parser.warnings());
  assembler.finish(animation, warnings);
  std::stable_sort(warnings.begin(), warnings.end(), [](const Diagnostic& a, const Diagnostic& b) {
    return a.where.line < b.where.line;
  });
  result.warnings = std::move(warnings);
  return result;
}

}  // namespace

FapReadResult FapReader::readFile(const std::string& path) {
  errno = 0;
  const std::unique_ptr<std::FILE, FileCloser> file(std::fopen(path.c_str(), "rb"));
  if (!file) throw FileError({path, 0, 0}, std::string("cannot open: ") + std::strerror(errno));
  struct stat info {};
  const bool regular = ::fstat(fileno(file.get()), &info) == 0 && S_ISREG(info.st_mode);
  const auto size = regular ? static_cast<std::size_t>(info.st_size) : std::size_t{0};
  LineSource lines(file.get(), path, kMaxLineLength);
  return readLines(lines, path, size);
}

FapReadResult FapReader::parse(std::string_view text, const std::string& displayName) {
  LineSource lines(text, displayName, kMaxLineLength);
  return readLines(lines, displayName, text.size());
}

}  // namespace lacrima::inline common
