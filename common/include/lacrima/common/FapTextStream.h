#pragma once
// FAP text that arrives in pieces: a TCP stream of the .fap syntax (the header optional, then a
// mask line and a value line per frame), or one frame per datagram. Both go through
// FapTextParser, so a stream gets the file reader's diagnostics and bounds; unlike a file, a
// stream never stops at a bad line: the problem is counted, the last one kept for the user, and
// the next frame is read.
//
// Memory is bounded whatever arrives: at most one line (FapTextParser::kMaxLineLength bytes) is
// held; a longer line is counted and skipped up to its newline.
#include <lacrima/common/FapTextParser.h>

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

namespace lacrima::inline common {

struct FapStreamCounters {
  long long frames = 0;          // frames decoded
  long long malformed = 0;       // lines (or datagrams) refused by the parser
  long long oversizedLines = 0;  // lines longer than the limit, skipped
  long long truncated = 0;       // a stream that ended inside a line or after a mask line
  long long moods = 0;           // mood lines read
};

class FapTextStream {
 public:
  using FrameHandler = std::function<void(const FapTextFrame&)>;
  using MoodHandler = std::function<void(const MoodLevels&)>;

  explicit FapTextStream(std::string displayName);

  // Appends bytes as they arrive; every frame they complete goes to `onFrame`, every mood line
  // to `onMood` (when given), in order.
  void feed(std::string_view bytes, const FrameHandler& onFrame, const MoodHandler& onMood = {});
  // The peer closed the stream: a partial line or a mask line without its value line is
  // counted as truncated. The stream can then start again (a new connection).
  void finish();

  const FapStreamCounters& counters() const { return counters_; }
  // The rate a header named, if one came.
  std::optional<double> frameRate() const;
  // The last problem, "name:line:column: message"; empty when none.
  const std::string& lastProblem() const { return lastProblem_; }
  // Bytes held waiting for the end of a line (at most kMaxLineLength).
  std::size_t bufferedBytes() const { return partial_.size(); }

 private:
  void line(std::string_view text, const FrameHandler& onFrame, const MoodHandler& onMood);

  FapTextParser parser_;
  std::string partial_;    // the start of a line whose newline has not come yet
  bool skipping_ = false;  // inside an over-long line, until its newline
  int lineNumber_ = 0;
  FapStreamCounters counters_;
  std::string lastProblem_;
};

// One datagram holding one frame: a mask line and its value line, optionally after a header
// line (which names the rate); or one mood line. Throws FileError naming `displayName`, the line
// and what was expected when it is not exactly that.
struct FapDatagram {
  FapTextFrame frame;  // when there is no mood
  std::optional<double> frameRate;
  std::optional<MoodLevels> mood;  // a mood line's moods, in place of a frame
};
FapDatagram decodeFapDatagram(std::string_view bytes, const std::string& displayName);

}  // namespace lacrima::inline common
