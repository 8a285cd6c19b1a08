#include <lacrima/common/FapReader.h>

#include "FapFrameAssembler.h"
#include "FapLineSource.h"
#include "FapTokenizer.h"

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
using detail::NumberStatus;
using detail::quoteToken;
using detail::WholeStatus;

// More frames than this, in the header or as a frame number, is not an animation anyone made:
// 10 million frames is 5 days at 22 fps.
constexpr std::int64_t kMaxFrameCount = 10'000'000;
// The shortest possible frame: 68 one-character mask tokens with blanks, then "0\n". Bounds
// the first allocation by the input's size whatever nframes claims.
constexpr std::size_t kMinBytesPerFrame = 137;
// High-level codes are mirrored into float channels; keep them where float is exact.
constexpr double kMaxHighLevelValue = 1 << 24;
constexpr const char* kHeaderForm = "'<version> <name> <fps> <nframes>'";

// Which channels one mask line sets, in the order their values follow on the value line.
struct FrameMask {
  ChannelMask bits;
  std::vector<int> lowChannels;  // channel indices of masked FAPs 3..70, ascending
  bool viseme = false;           // FAP 1
  bool expression = false;       // FAP 2

  std::size_t scalarTokens() const {
    return 1 + lowChannels.size() + (viseme ? 1 : 0) + (expression ? 1 : 0);
  }
  std::size_t groupedTokens() const {
    return 1 + lowChannels.size() + (viseme ? 4 : 0) + (expression ? 6 : 0);
  }
};

bool readFrameNumber(std::string_view token, std::int64_t& number) {
  return detail::parseDigits(token, kMaxFrameCount, number) == WholeStatus::Ok &&
         number <= kMaxFrameCount;
}

// A low-level value is any finite number, but tear channels hold whole particle counts.
bool acceptableValue(double value, int channel) {
  return !isTearChannel(fapNumber(channel)) ||
         (value >= 0 && value <= kMaxTearParticles && value == std::floor(value));
}

struct FileCloser {
  void operator()(std::FILE* file) const { std::fclose(file); }
};

class Parser {
 public:
  Parser(LineSource& lines, const std::string& displayName, std::size_t inputSize)
      : lines_(lines),
        displayName_(displayName),
        inputSize_(inputSize),
        assembler_(displayName, FapReader::kMaxFilledFrames) {}

  FapReadResult run();

 private:
  bool nextLine();
  void tokenizeOrFail();
  void readHeader(FapReadResult& result);
  double headerNumber(std::size_t index, const char* expected);
  void readMask();
  void readValues();
  bool scanPlainValues(FapValues& values, std::int64_t& number, int& numberColumn) const;
  void readHighLevel(std::size_t& t, bool grouped, FapValues& values);
  int wholeAt(std::size_t t, int fap, const char* field) const;
  [[noreturn]] void failTokenCount() const;
  [[noreturn]] void failFrameNumber(std::string_view token) const;
  [[noreturn]] void failTearCount(std::string_view token, int channel) const;
  [[noreturn]] void failNumber(std::string_view token, NumberStatus status,
                               const std::string& what) const;

  int columnOf(std::string_view token) const {
    return static_cast<int>(token.data() - line_.data()) + 1;
  }
  // Where a missing token would start: after the last token and one blank.
  int columnAfterTokens() const {
    if (tokens_.empty()) return 1;
    return columnOf(tokens_.back()) + static_cast<int>(tokens_.back().size()) + 1;
  }
  [[noreturn]] void fail(int column, const std::string& message) const {
    throw FileError({displayName_, lines_.lineNumber(), column}, message);
  }
  void warn(int column, const std::string& message) {
    warnings_.push_back({{displayName_, lines_.lineNumber(), column}, message});
  }

  LineSource& lines_;
  const std::string& displayName_;
  std::size_t inputSize_;
  std::string_view line_;  // the current line as read: columns count from its start
  std::string_view text_;  // the same without a byte order mark
  std::vector<std::string_view> tokens_;
  FrameMask mask_;
  std::string maskText_;  // the last mask line parsed: files repeat it in every frame
  ChannelMask animated_;
  FrameAssembler assembler_;
  Warnings warnings_;
};

FapReadResult Parser::run() {
  FapReadResult result;
  readHeader(result);
  while (nextLine()) {
    readMask();
    const int maskLine = lines_.lineNumber();
    if (!nextLine()) {
      throw FileError({displayName_, maskLine, 0},
                      "the file ends after a mask line: expected its value line "
                      "'<frame> <values>'");
    }
    readValues();
  }
  result.animation.animated = animated_;
  assembler_.finish(result.animation, warnings_);
  std::stable_sort(
      warnings_.begin(), warnings_.end(),
      [](const Diagnostic& a, const Diagnostic& b) { return a.where.line < b.where.line; });
  result.warnings = std::move(warnings_);
  return result;
}

// Moves to the next line that holds tokens, skipping blank and comment lines; false at the end.
bool Parser::nextLine() {
  while (lines_.next(line_)) {
    text_ = line_;
    // Windows editors may start UTF-8 text with a byte order mark.
    if (lines_.lineNumber() == 1 && text_.starts_with("\xEF\xBB\xBF")) text_.remove_prefix(3);
    detail::TokenCursor cursor(text_);
    if (!cursor.next().empty()) return true;
    if (cursor.controlByteInRest() >= 0) tokenizeOrFail();  // reports the byte
  }
  return false;
}

void Parser::tokenizeOrFail() {
  const long bad = detail::tokenizeLine(text_, tokens_);
  if (bad < 0) return;
  char byte[8];
  std::snprintf(byte, sizeof byte, "0x%02X",
                static_cast<unsigned char>(text_[static_cast<std::size_t>(bad)]));
  fail(columnOf(text_.substr(static_cast<std::size_t>(bad))),
       std::string("binary data (control byte ") + byte + "): expected the text of a .fap file");
}

void Parser::readHeader(FapReadResult& result) {
  if (!nextLine()) {
    throw FileError(
        {displayName_, 0, 0},
        std::string(lines_.sawInput() ? "no header: the file holds only blank lines and comments"
                                      : "empty file") +
            "; expected the header " + kHeaderForm);
  }
  tokenizeOrFail();
  const std::size_t n = tokens_.size();
  if (n < 4) {
    fail(columnAfterTokens(), std::string("expected the header ") + kHeaderForm + ", found " +
                                  std::to_string(n) + (n == 1 ? " token" : " tokens"));
  }
  FapAnimation& animation = result.animation;

  const double version = headerNumber(0, "a version number such as 2.1");
  if (version <= 0)
    fail(1, "the version must be a positive number, found " + quoteToken(tokens_[0]));
  if (version != 2.0 && version != 2.1) {
    warn(1, "unknown version " + std::string(tokens_[0]) +
                " (known: 2.0 and 2.1): read like 2.1, other players may refuse it");
  }
  animation.version = std::string(tokens_[0]);

  animation.fps = headerNumber(n - 2, "the frame rate (frames per second)");
  if (!(animation.fps > 0 && animation.fps <= 1000)) {
    fail(columnOf(tokens_[n - 2]),
         "the frame rate must be above 0 and at most 1000, found " + quoteToken(tokens_[n - 2]));
  }

  const std::string_view countToken = tokens_[n - 1];
  std::int64_t frames = 0;
  switch (detail::parseDigits(countToken, kMaxFrameCount, frames)) {
    case WholeStatus::NotWhole:
      fail(columnOf(countToken),
           "expected the number of frames (a whole number), found " + quoteToken(countToken));
    case WholeStatus::Negative:
      fail(columnOf(countToken),
           "the number of frames must not be negative, found " + quoteToken(countToken));
    case WholeStatus::Ok:
      break;
  }
  if (frames > kMaxFrameCount) {
    fail(columnOf(countToken), "the number of frames " + quoteToken(countToken) +
                                   " is absurd (more than " + std::to_string(kMaxFrameCount) + ")");
  }
  result.headerFrameCount = static_cast<int>(frames);

  animation.name = std::string(tokens_[1]);
  for (std::size_t i = 2; i + 2 < n; ++i) animation.name += ' ' + std::string(tokens_[i]);
  if (n > 4) {
    warn(columnOf(tokens_[1]), "the name '" + animation.name +
                                   "' contains spaces: other players will misread this header");
  }

  const std::size_t fitsInInput = inputSize_ / kMinBytesPerFrame + 1;
  assembler_.setHeader(result.headerFrameCount, lines_.lineNumber(), columnOf(countToken),
                       std::min(static_cast<std::size_t>(frames), fitsInInput));
}

double Parser::headerNumber(std::size_t index, const char* expected) {
  double value = 0;
  const NumberStatus status = detail::parseNumber(tokens_[index], value);
  if (status != NumberStatus::Ok) failNumber(tokens_[index], status, expected);
  return value;
}

void Parser::readMask() {
  if (text_ == maskText_) return;  // same bytes as the last mask: already checked and counted
  tokenizeOrFail();
  const std::size_t n = tokens_.size();
  // A wrong token first: it is the more precise message when a line has both faults.
  for (std::size_t i = 0; i < n; ++i) {
    const std::string_view token = tokens_[i];
    if (token.size() != 1 || (token[0] != '0' && token[0] != '1')) {
      fail(columnOf(token), "a mask token is 0 or 1, found " + quoteToken(token) + " (token " +
                                std::to_string(i + 1) + ")");
    }
  }
  if (n != kFapCount && n != kChannelCount) {
    const int column = n < kFapCount
                           ? columnAfterTokens()
                           : columnOf(tokens_[n < kChannelCount ? kFapCount : kChannelCount]);
    fail(column, "expected a mask line of 68 or 70 tokens (each 0 or 1), found " +
                     std::to_string(n) + " tokens");
  }
  mask_.bits.reset();
  mask_.lowChannels.clear();
  for (std::size_t i = 0; i < n; ++i) {
    if (tokens_[i][0] != '1') continue;
    mask_.bits.set(i);
    if (!isHighLevelFap(fapNumber(static_cast<int>(i))))
      mask_.lowChannels.push_back(static_cast<int>(i));
  }
  mask_.viseme = mask_.bits.test(channelIndex(1));
  mask_.expression = mask_.bits.test(channelIndex(2));
  animated_ |= mask_.bits;
  maskText_.assign(text_);
}

void Parser::readValues() {
  if (!mask_.viseme && !mask_.expression) {
    FapValues values{};
    std::int64_t number = 0;
    int column = 0;
    if (scanPlainValues(values, number, column)) {
      assembler_.add(number, lines_.lineNumber(), column) = values;
      return;
    }
  }
  // FAP 1/2 (two dialects to tell apart) or a line with a problem: the precise path, which
  // throws with the exact place for every problem the fast path declined.
  tokenizeOrFail();
  const std::size_t count = tokens_.size();
  const std::size_t grouped = mask_.groupedTokens();
  if (count != mask_.scalarTokens() && count != grouped) failTokenCount();

  std::int64_t number = 0;
  if (!readFrameNumber(tokens_[0], number)) failFrameNumber(tokens_[0]);
  FapValues& values = assembler_.add(number, lines_.lineNumber(), columnOf(tokens_[0]));
  std::size_t t = 1;
  if (mask_.viseme || mask_.expression) readHighLevel(t, count == grouped, values);
  for (const int channel : mask_.lowChannels) {
    const std::string_view token = tokens_[t++];
    double value = 0;
    const NumberStatus status = detail::parseNumber(token, value);
    if (status != NumberStatus::Ok)
      failNumber(token, status, "a number for FAP " + std::to_string(fapNumber(channel)));
    if (!acceptableValue(value, channel)) failTearCount(token, channel);
    values[static_cast<std::size_t>(channel)] = static_cast<float>(value);
  }
}

// The value line of a frame without FAP 1/2, in one pass and without allocating. False when
// anything is off; the caller then reports it precisely.
bool Parser::scanPlainValues(FapValues& values, std::int64_t& number, int& numberColumn) const {
  detail::TokenCursor cursor(text_);
  const std::string_view first = cursor.next();
  if (!readFrameNumber(first, number)) return false;
  numberColumn = columnOf(first);
  std::string_view token;
  double value = 0;
  for (const int channel : mask_.lowChannels) {
    if (cursor.nextNumber(token, value) != NumberStatus::Ok || !acceptableValue(value, channel))
      return false;
    values[static_cast<std::size_t>(channel)] = static_cast<float>(value);
  }
  return cursor.next().empty() && !cursor.stoppedEarly();
}

void Parser::readHighLevel(std::size_t& t, bool grouped, FapValues& values) {
  HighLevelFrame& high = assembler_.highLevel();
  if (mask_.viseme) {
    VisemeParams& v = high.viseme;
    v.select1 = wholeAt(t++, 1, "viseme_select1");
    if (grouped) {
      v.select2 = wholeAt(t++, 1, "viseme_select2");
      v.blend = wholeAt(t++, 1, "viseme_blend");
      v.define = wholeAt(t++, 1, "viseme_def") != 0;
    }
  }
  if (mask_.expression) {
    ExpressionParams& e = high.expression;
    e.select1 = wholeAt(t++, 2, "expression_select1");
    if (grouped) {
      e.intensity1 = wholeAt(t++, 2, "expression_intensity1");
      e.select2 = wholeAt(t++, 2, "expression_select2");
      e.intensity2 = wholeAt(t++, 2, "expression_intensity2");
      e.initFace = wholeAt(t++, 2, "init_face") != 0;
      e.define = wholeAt(t++, 2, "expression_def") != 0;
    } else {
      e.intensity1 = 63;  // a bare expression code means that expression at full strength
    }
  }
  values[channelIndex(1)] = static_cast<float>(high.viseme.select1);
  values[channelIndex(2)] = static_cast<float>(high.expression.select1);
}

void Parser::failFrameNumber(std::string_view token) const {
  std::int64_t number = 0;
  switch (detail::parseDigits(token, kMaxFrameCount, number)) {
    case WholeStatus::NotWhole:
      fail(columnOf(token),
           "expected a frame number (a whole number from 0), found " + quoteToken(token));
    case WholeStatus::Negative:
      fail(columnOf(token), "frame numbers start at 0, found " + quoteToken(token));
    case WholeStatus::Ok:
      break;
  }
  fail(columnOf(token), "frame number " + quoteToken(token) + " is absurd (more than " +
                            std::to_string(kMaxFrameCount) + " frames)");
}

void Parser::failTearCount(std::string_view token, int channel) const {
  fail(columnOf(token), "tear channel " + std::to_string(fapNumber(channel)) +
                            " holds a whole number of particles from 0 to " +
                            std::to_string(kMaxTearParticles) + ", found " + quoteToken(token));
}

int Parser::wholeAt(std::size_t t, int fap, const char* field) const {
  const std::string_view token = tokens_[t];
  double value = 0;
  const NumberStatus status = detail::parseNumber(token, value);
  const std::string what = "FAP " + std::to_string(fap) + " " + field;
  if (status != NumberStatus::Ok) failNumber(token, status, "a number for " + what);
  if (!(value >= 0 && value <= kMaxHighLevelValue && value == std::floor(value)))
    fail(columnOf(token), what + " must be a whole number from 0 to " +
                              std::to_string(static_cast<long>(kMaxHighLevelValue)) + ", found " +
                              quoteToken(token));
  return static_cast<int>(value);
}

void Parser::failTokenCount() const {
  const std::size_t count = tokens_.size();
  const std::size_t scalar = mask_.scalarTokens();
  const std::size_t grouped = mask_.groupedTokens();
  const int column = count < scalar    ? columnAfterTokens()
                     : count > grouped ? columnOf(tokens_[grouped])
                                       : columnOf(tokens_[scalar]);
  const std::string found = ", found " + std::to_string(count);
  if (scalar == grouped) {
    fail(column, "expected " + std::to_string(scalar) +
                     " tokens on the value line (the frame number, then one value per masked FAP)" +
                     found);
  }
  fail(column, "expected " + std::to_string(grouped) +
                   " tokens on the value line (frame number, FAP 1/2 grouped as 4/6 numbers, "
                   "one value per other masked FAP) or " +
                   std::to_string(scalar) + " (FAP 1/2 as one number each)" + found);
}

void Parser::failNumber(std::string_view token, NumberStatus status,
                        const std::string& what) const {
  switch (status) {
    case NumberStatus::NotFinite:
      fail(columnOf(token), "expected " + what + ", found " + quoteToken(token) + " (not finite)");
    case NumberStatus::OutOfRange:
      fail(columnOf(token),
           "expected " + what + ", found " + quoteToken(token) + " (out of range)");
    case NumberStatus::NotANumber:
    case NumberStatus::Ok:
      break;
  }
  fail(columnOf(token), "expected " + what + ", found " + quoteToken(token));
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
  return Parser(lines, path, size).run();
}

FapReadResult FapReader::parse(std::string_view text, const std::string& displayName) {
  LineSource lines(text, displayName, kMaxLineLength);
  return Parser(lines, displayName, text.size()).run();
}

}  // namespace lacrima::inline common
