#include <lacrima/common/FapTextParser.h>

#include "FapTokenizer.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace lacrima::inline common {

namespace {

using detail::NumberStatus;
using detail::quoteToken;
using detail::WholeStatus;

// High-level codes are mirrored into float channels; keep them where float is exact.
constexpr double kMaxHighLevelValue = 1 << 24;
constexpr const char* kHeaderForm = "'<version> <name> <fps> <nframes>'";

bool readFrameNumber(std::string_view token, std::int64_t& number) {
  return detail::parseDigits(token, FapTextParser::kMaxFrameCount, number) == WholeStatus::Ok &&
         number <= FapTextParser::kMaxFrameCount;
}

// A low-level value is any finite number, but tear channels hold whole particle counts.
bool acceptableValue(double value, int channel) {
  return !isTearChannel(fapNumber(channel)) ||
         (value >= 0 && value <= kMaxTearParticles && value == std::floor(value));
}

}  // namespace

std::size_t FapTextParser::Mask::scalarTokens() const {
  return 1 + lowChannels.size() + (viseme ? 1 : 0) + (expression ? 1 : 0);
}

std::size_t FapTextParser::Mask::groupedTokens() const {
  return 1 + lowChannels.size() + (viseme ? 4 : 0) + (expression ? 6 : 0);
}

FapTextParser::FapTextParser(std::string displayName, Header header)
    : displayName_(std::move(displayName)), headerRule_(header) {}

FapTextParser::Event FapTextParser::feed(std::string_view line, int lineNumber) {
  if (!startLine(line, lineNumber)) return Event::None;
  if (maskLine_ != 0) {
    maskLine_ = 0;  // whatever happens to this line, the next one starts a frame again
    readValues();
    return Event::Frame;
  }
  if (isMoodLine()) {
    readMood();
    return Event::Mood;
  }
  const bool header = headerRule_ == Header::Required ? !sawHeader_ : !looksLikeMask();
  if (header) {
    readHeader();
    return Event::Header;
  }
  readMask();
  maskLine_ = lineNumber;
  return Event::None;
}

// False for a line without tokens (blank or comment); throws for binary data in it.
bool FapTextParser::startLine(std::string_view line, int lineNumber) {
  lineNumber_ = lineNumber;
  line_ = line;
  text_ = line;
  // Windows editors may start UTF-8 text with a byte order mark.
  if (lineNumber == 1 && text_.starts_with("\xEF\xBB\xBF")) text_.remove_prefix(3);
  detail::TokenCursor cursor(text_);
  if (!cursor.next().empty()) return true;
  if (cursor.controlByteInRest() >= 0) tokenizeOrFail();  // reports the byte
  return false;
}

// A stream's line that starts with a mask token; anything else is read as a header.
bool FapTextParser::looksLikeMask() const {
  const std::string_view first = detail::TokenCursor(text_).next();
  return first == "0" || first == "1";
}

bool FapTextParser::isMoodLine() const { return detail::TokenCursor(text_).next() == "mood"; }

// `mood name=value ...`, each mood at most once, each value in [0, 1]; the rest are 0.
void FapTextParser::readMood() {
  tokenizeOrFail();
  if (headerRule_ == Header::Required)
    fail(1, "a mood line is a live stream's message (docs/live.md): expected the header " +
                std::string(kHeaderForm) + " or a frame in a file");
  MoodLevels levels;
  std::array<bool, kMoodCount> named{};
  for (std::size_t t = 1; t < tokens_.size(); ++t) {
    const std::string_view token = tokens_[t];
    if (token.find(',') != std::string_view::npos)
      fail(columnOf(token) + static_cast<int>(token.find(',')),
           "expected blanks between moods ('mood sadness=0.8 anger=0.2'), found ','");
    MoodLevels one;
    try {
      one = parseMoodLevels(token);
    } catch (const std::invalid_argument& e) {
      fail(columnOf(token),
           std::string(e.what()) + " (a mood line reads 'mood sadness=0.8 anger=0')");
    }
    const std::string_view name = token.substr(0, token.find('='));
    const Mood mood = *moodByName(name);  // parseMoodLevels knew it
    const auto m = static_cast<std::size_t>(mood);
    if (named[m]) fail(columnOf(token), "mood '" + std::string(name) + "' is named twice");
    named[m] = true;
    levels[mood] = one[mood];
  }
  mood_ = levels;
}

void FapTextParser::tokenizeOrFail() {
  const long bad = detail::tokenizeLine(text_, tokens_);
  if (bad < 0) return;
  char byte[8];
  std::snprintf(byte, sizeof byte, "0x%02X",
                static_cast<unsigned char>(text_[static_cast<std::size_t>(bad)]));
  fail(columnOf(text_.substr(static_cast<std::size_t>(bad))),
       std::string("binary data (control byte ") + byte + "): expected the text of a .fap file");
}

int FapTextParser::columnOf(std::string_view token) const {
  return static_cast<int>(token.data() - line_.data()) + 1;
}

// Where a missing token would start: after the last token and one blank.
int FapTextParser::columnAfterTokens() const {
  if (tokens_.empty()) return 1;
  return columnOf(tokens_.back()) + static_cast<int>(tokens_.back().size()) + 1;
}

void FapTextParser::fail(int column, const std::string& message) const {
  throw FileError({displayName_, lineNumber_, column}, message);
}

void FapTextParser::warn(int column, const std::string& message) {
  warnings_.push_back({{displayName_, lineNumber_, column}, message});
}

void FapTextParser::readHeader() {
  tokenizeOrFail();
  const std::size_t n = tokens_.size();
  if (n < 4) {
    fail(columnAfterTokens(), std::string("expected the header ") + kHeaderForm + ", found " +
                                  std::to_string(n) + (n == 1 ? " token" : " tokens"));
  }
  FapTextHeader header;
  header.line = lineNumber_;

  const double version = headerNumber(0, "a version number such as 2.1");
  if (version <= 0)
    fail(1, "the version must be a positive number, found " + quoteToken(tokens_[0]));
  if (version != 2.0 && version != 2.1) {
    warn(1, "unknown version " + std::string(tokens_[0]) +
                " (known: 2.0 and 2.1): read like 2.1, other players may refuse it");
  }
  header.version = std::string(tokens_[0]);

  header.fps = headerNumber(n - 2, "the frame rate (frames per second)");
  if (!(header.fps > 0 && header.fps <= 1000)) {
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
  header.frameCount = static_cast<int>(frames);
  header.frameCountColumn = columnOf(countToken);

  header.name = std::string(tokens_[1]);
  for (std::size_t i = 2; i + 2 < n; ++i) header.name += ' ' + std::string(tokens_[i]);
  if (n > 4) {
    warn(columnOf(tokens_[1]),
         "the name '" + header.name + "' contains spaces: other players will misread this header");
  }
  header_ = std::move(header);
  sawHeader_ = true;
}

double FapTextParser::headerNumber(std::size_t index, const char* expected) {
  double value = 0;
  const NumberStatus status = detail::parseNumber(tokens_[index], value);
  if (status != NumberStatus::Ok) failNumber(tokens_[index], static_cast<int>(status), expected);
  return value;
}

void FapTextParser::readMask() {
  if (text_ == maskText_) return;  // same bytes as the last mask: already checked
  maskText_.clear();               // until this one is known to be good
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
  maskText_.assign(text_);
}

void FapTextParser::readValues() {
  frame_.values.fill(0.0F);
  frame_.mask = mask_.bits;
  frame_.highLevel.reset();
  if (!mask_.viseme && !mask_.expression && scanPlainValues()) return;
  // FAP 1/2 (two dialects to tell apart) or a line with a problem: the precise path, which
  // throws with the exact place for every problem the fast path declined.
  tokenizeOrFail();
  const std::size_t count = tokens_.size();
  const std::size_t grouped = mask_.groupedTokens();
  if (count != mask_.scalarTokens() && count != grouped) failTokenCount();

  if (!readFrameNumber(tokens_[0], frame_.number)) failFrameNumber(tokens_[0]);
  frame_.line = lineNumber_;
  frame_.column = columnOf(tokens_[0]);
  frame_.values.fill(0.0F);
  std::size_t t = 1;
  if (mask_.viseme || mask_.expression) readHighLevel(t, count == grouped);
  for (const int channel : mask_.lowChannels) {
    const std::string_view token = tokens_[t++];
    double value = 0;
    const NumberStatus status = detail::parseNumber(token, value);
    if (status != NumberStatus::Ok)
      failNumber(token, static_cast<int>(status),
                 "a number for FAP " + std::to_string(fapNumber(channel)));
    if (!acceptableValue(value, channel)) failTearCount(token, channel);
    frame_.values[static_cast<std::size_t>(channel)] = static_cast<float>(value);
  }
}

// The value line of a frame without FAP 1/2, in one pass and without allocating. False when
// anything is off; the caller then reports it precisely.
bool FapTextParser::scanPlainValues() {
  detail::TokenCursor cursor(text_);
  const std::string_view first = cursor.next();
  if (!readFrameNumber(first, frame_.number)) return false;
  frame_.line = lineNumber_;
  frame_.column = columnOf(first);
  std::string_view token;
  double value = 0;
  for (const int channel : mask_.lowChannels) {
    if (cursor.nextNumber(token, value) != NumberStatus::Ok || !acceptableValue(value, channel))
      return false;
    frame_.values[static_cast<std::size_t>(channel)] = static_cast<float>(value);
  }
  return cursor.next().empty() && !cursor.stoppedEarly();
}

void FapTextParser::readHighLevel(std::size_t& t, bool grouped) {
  HighLevelFrame& high = frame_.highLevel.emplace();
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
  frame_.values[channelIndex(1)] = static_cast<float>(high.viseme.select1);
  frame_.values[channelIndex(2)] = static_cast<float>(high.expression.select1);
}

void FapTextParser::failFrameNumber(std::string_view token) const {
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

void FapTextParser::failTearCount(std::string_view token, int channel) const {
  fail(columnOf(token), "tear channel " + std::to_string(fapNumber(channel)) +
                            " holds a whole number of particles from 0 to " +
                            std::to_string(kMaxTearParticles) + ", found " + quoteToken(token));
}

int FapTextParser::wholeAt(std::size_t t, int fap, const char* field) const {
  const std::string_view token = tokens_[t];
  double value = 0;
  const NumberStatus status = detail::parseNumber(token, value);
  const std::string what = "FAP " + std::to_string(fap) + " " + field;
  if (status != NumberStatus::Ok)
    failNumber(token, static_cast<int>(status), "a number for " + what);
  if (!(value >= 0 && value <= kMaxHighLevelValue && value == std::floor(value)))
    fail(columnOf(token), what + " must be a whole number from 0 to " +
                              std::to_string(static_cast<long>(kMaxHighLevelValue)) + ", found " +
                              quoteToken(token));
  return static_cast<int>(value);
}

void FapTextParser::failTokenCount() const {
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

void FapTextParser::failNumber(std::string_view token, int status, const std::string& what) const {
  switch (static_cast<NumberStatus>(status)) {
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

}  // namespace lacrima::inline common
