#include <lacrima/common/FapTextStream.h>

#include <algorithm>
#include <cstring>
#include <limits>

namespace lacrima::inline common {

FapTextStream::FapTextStream(std::string displayName)
    : parser_(std::move(displayName), FapTextParser::Header::Optional) {}

void FapTextStream::feed(std::string_view bytes, const FrameHandler& onFrame,
                         const MoodHandler& onMood) {
  while (!bytes.empty()) {
    const void* found = std::memchr(bytes.data(), '\n', bytes.size());
    const std::size_t length =
        found ? static_cast<std::size_t>(static_cast<const char*>(found) - bytes.data())
              : bytes.size();
    const std::string_view piece = bytes.substr(0, length);
    bytes.remove_prefix(found ? length + 1 : length);
    if (!skipping_ && partial_.size() + piece.size() > FapTextParser::kMaxLineLength) {
      ++counters_.oversizedLines;
      ++lineNumber_;
      lastProblem_ = SourceLocation{parser_.displayName(), lineNumber_, 0}.toString() +
                     ": line is longer than " + std::to_string(FapTextParser::kMaxLineLength) +
                     " bytes: skipped (a real value line is a few KiB)";
      partial_.clear();
      parser_.dropPendingMask();
      skipping_ = true;
    }
    if (skipping_) {
      if (found) skipping_ = false;  // the over-long line ends here
      continue;
    }
    if (!found) {
      partial_.append(piece);
      continue;
    }
    ++lineNumber_;
    if (partial_.empty()) {
      line(piece, onFrame, onMood);
    } else {
      partial_.append(piece);
      line(partial_, onFrame, onMood);
      partial_.clear();
    }
  }
}

void FapTextStream::line(std::string_view text, const FrameHandler& onFrame,
                         const MoodHandler& onMood) {
  // A stream may run for days: keep its line numbers positive (line 1 alone may hold a BOM).
  if (lineNumber_ == std::numeric_limits<int>::max()) lineNumber_ = 2;
  parser_.warnings().clear();  // a stream's warnings would pile up; its header is its own
  try {
    const FapTextParser::Event event = parser_.feed(text, lineNumber_);
    if (event == FapTextParser::Event::Frame) {
      ++counters_.frames;
      onFrame(parser_.frame());
    } else if (event == FapTextParser::Event::Mood) {
      ++counters_.moods;
      if (onMood) onMood(parser_.mood());
    }
  } catch (const FileError& e) {
    ++counters_.malformed;
    lastProblem_ = e.what();
  }
}

void FapTextStream::finish() {
  if (!partial_.empty() || parser_.pendingMaskLine() != 0 || skipping_) {
    ++counters_.truncated;
    lastProblem_ = SourceLocation{parser_.displayName(), lineNumber_ + 1, 0}.toString() +
                   ": the stream ended inside a frame (expected a mask line and its value line)";
  }
  partial_.clear();
  skipping_ = false;
  parser_.dropPendingMask();
}

std::optional<double> FapTextStream::frameRate() const {
  if (!parser_.sawHeader()) return std::nullopt;
  return parser_.header().fps;
}

FapDatagram decodeFapDatagram(std::string_view bytes, const std::string& displayName) {
  FapTextParser parser(displayName, FapTextParser::Header::Optional);
  FapDatagram datagram;
  bool haveFrame = false;
  int lineNumber = 0;
  while (!bytes.empty()) {
    const std::size_t end = std::min(bytes.find('\n'), bytes.size());
    const std::string_view text = bytes.substr(0, end);
    bytes.remove_prefix(std::min(end + 1, bytes.size()));
    ++lineNumber;
    if (text.size() > FapTextParser::kMaxLineLength) {
      throw FileError({displayName, lineNumber, 0},
                      "line is longer than " + std::to_string(FapTextParser::kMaxLineLength) +
                          " bytes: expected a mask line and a value line");
    }
    const FapTextParser::Event event = parser.feed(text, lineNumber);
    if (event == FapTextParser::Event::None) continue;
    if (haveFrame) {
      throw FileError({displayName, lineNumber, 0},
                      datagram.mood ? "a datagram holds one mood line: expected nothing after it"
                                    : "a datagram holds one frame: expected nothing after its "
                                      "value line");
    }
    if (event == FapTextParser::Event::Mood) {
      datagram.mood = parser.mood();
      haveFrame = true;
    } else if (event == FapTextParser::Event::Header) {
      datagram.frameRate = parser.header().fps;
    } else {
      datagram.frame = parser.frame();
      haveFrame = true;
    }
  }
  if (!haveFrame) {
    throw FileError({displayName, parser.pendingMaskLine(), 0},
                    parser.pendingMaskLine() != 0
                        ? "the datagram ends after a mask line: expected its value line "
                          "'<frame> <values>'"
                        : "the datagram holds no frame: expected a mask line and a value line "
                          "(or a mood line)");
  }
  return datagram;
}

}  // namespace lacrima::inline common
