#pragma once
// The .fap text syntax, one line at a time: the one parser behind FapReader (a whole file) and
// the live streams (FapTextStream: bytes from a socket; one frame per datagram). It reads the
// header, the mask lines and the value lines exactly as docs/fap.md describes them, and throws
// FileError("name:line:column: what was expected") for a malformed line, so a file and a stream
// get the same diagnostics and the same bounds.
//
// Frames come out in the order they are written, not placed by number: a file's reader places
// and fills them (FapReader), a stream shows the newest.
//
// A stream may also carry mood lines (docs/live.md): `mood sadness=0.8 anger=0.2` sets the
// crying generator's moods instead of sending every channel. Moods the line does not name are
// 0; `mood` alone is neutral. A file holds frames only: there a mood line is an error.
#include <lacrima/common/Diagnostics.h>
#include <lacrima/common/FapAnimation.h>
#include <lacrima/common/mood/Moods.h>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lacrima::inline common {

// The header line `version name fps nframes`.
struct FapTextHeader {
  std::string version = "2.1";
  std::string name = "lacrima";
  double fps = 22.0;
  int frameCount = 0;  // nframes as written
  int line = 0;        // where it was written
  int frameCountColumn = 0;
};

// One frame: a mask line and its value line. Masked-off channels are 0 (the neutral face).
struct FapTextFrame {
  std::int64_t number = 0;  // as written on the value line
  int line = 0;             // of the value line
  int column = 0;           // of the frame number
  FapValues values{};
  ChannelMask mask;                         // the channels this frame sets
  std::optional<HighLevelFrame> highLevel;  // when FAP 1 or 2 is masked
};

class FapTextParser {
 public:
  // Longest physical line accepted, in files and streams alike. A real value line is < 4 KiB.
  static constexpr std::size_t kMaxLineLength = 64 * 1024;
  // More frames than this, in the header or as a frame number, is not an animation anyone made:
  // 10 million frames is 5 days at 22 fps.
  static constexpr std::int64_t kMaxFrameCount = 10'000'000;

  // A file starts with its header; a stream may leave it out (and may send one again between
  // frames, to name its rate).
  enum class Header { Required, Optional };
  enum class Event { None, Header, Frame, Mood };

  FapTextParser(std::string displayName, Header header);

  // One physical line without its '\n' (a CR stays: it is a blank), numbered `lineNumber`
  // (1-based; line 1 may start with a UTF-8 byte order mark). Returns Header when the line was
  // a header (header()), Frame when it completed a frame (frame()), Mood for a stream's mood
  // line (mood()), None for a blank, a comment or a mask line. Throws FileError for a malformed
  // line; the parser then expects a mask line (or a header) again, so a stream goes on with the
  // next frame.
  Event feed(std::string_view line, int lineNumber);

  // Forgets a mask line still waiting for its value line (a datagram or connection that ended).
  void dropPendingMask() { maskLine_ = 0; }

  bool sawHeader() const { return sawHeader_; }
  const FapTextHeader& header() const { return header_; }
  const FapTextFrame& frame() const { return frame_; }
  const MoodLevels& mood() const { return mood_; }
  // Line of a mask line still waiting for its value line; 0 when none is.
  int pendingMaskLine() const { return maskLine_; }
  // Warnings so far (an unknown version, a name with spaces), in line order.
  Warnings& warnings() { return warnings_; }
  const std::string& displayName() const { return displayName_; }

 private:
  struct Mask {
    ChannelMask bits;
    std::vector<int> lowChannels;  // channel indices of masked FAPs 3..70, ascending
    bool viseme = false;           // FAP 1
    bool expression = false;       // FAP 2
    std::size_t scalarTokens() const;
    std::size_t groupedTokens() const;
  };

  bool startLine(std::string_view line, int lineNumber);
  void tokenizeOrFail();
  bool looksLikeMask() const;
  bool isMoodLine() const;
  void readMood();
  void readHeader();
  double headerNumber(std::size_t index, const char* expected);
  void readMask();
  void readValues();
  bool scanPlainValues();
  void readHighLevel(std::size_t& t, bool grouped);
  int wholeAt(std::size_t t, int fap, const char* field) const;
  [[noreturn]] void failTokenCount() const;
  [[noreturn]] void failFrameNumber(std::string_view token) const;
  [[noreturn]] void failTearCount(std::string_view token, int channel) const;
  [[noreturn]] void failNumber(std::string_view token, int status, const std::string& what) const;
  [[noreturn]] void fail(int column, const std::string& message) const;
  void warn(int column, const std::string& message);
  int columnOf(std::string_view token) const;
  int columnAfterTokens() const;

  std::string displayName_;
  Header headerRule_;
  bool sawHeader_ = false;
  FapTextHeader header_;
  int lineNumber_ = 0;
  std::string_view line_;  // the current line as given: columns count from its start
  std::string_view text_;  // the same without a byte order mark
  std::vector<std::string_view> tokens_;
  Mask mask_;
  std::string maskText_;  // the last mask line parsed: files repeat it in every frame
  int maskLine_ = 0;      // a mask line waiting for its value line
  FapTextFrame frame_;
  MoodLevels mood_;
  Warnings warnings_;
};

}  // namespace lacrima::inline common
