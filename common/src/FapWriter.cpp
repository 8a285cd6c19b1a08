#include <lacrima/common/AtomicSave.h>
#include <lacrima/common/FapWriter.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <vector>

namespace lacrima::inline common {

namespace {

// Written values stay where every reader's integer parsing works (GR: Integer.parseInt).
constexpr double kMaxWrittenValue = 2147483647.0;
constexpr std::size_t kMaxNumberChars = 11;  // "-2147483647"
constexpr int kMaxFps = 1000;                // what FapReader accepts

std::string formatNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

// One token that no reader splits or mistakes for a comment.
std::string headerName(const std::string& name) {
  if (name.empty()) return "lacrima";
  std::string out = name;
  for (char& c : out) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte <= ' ' || byte == 0x7f) c = '_';
  }
  if (out.front() == '#') out.front() = '_';
  return out;
}

class TextWriter {
 public:
  TextWriter(const FapAnimation& animation, const FapWriteOptions& options, Warnings* warnings,
             const std::string& file)
      : animation_(animation), options_(options), warnings_(warnings), file_(file) {}

  std::string write();

 private:
  long fps();
  void chooseChannels();
  std::string maskLine() const;
  int whole(float value, bool tear);
  void warn(const std::string& message) {
    if (!warnings_) return;
    Diagnostic diagnostic;
    diagnostic.where.file = file_;
    diagnostic.message = message;
    warnings_->push_back(std::move(diagnostic));
  }

  const FapAnimation& animation_;
  const FapWriteOptions& options_;
  Warnings* warnings_;
  std::string file_;
  int maskTokens_ = kFapCount;
  std::vector<int> channels_;  // masked channel indices, ascending
  int nonFinite_ = 0;
  int clamped_ = 0;
};

std::string TextWriter::write() {
  chooseChannels();
  const std::string header = "2.1 " + headerName(animation_.name) + ' ' + std::to_string(fps()) +
                             ' ' + std::to_string(animation_.frames.size()) + '\n';
  const std::string mask = maskLine();

  const std::size_t frames = animation_.frames.size();
  const std::size_t perFrame =
      mask.size() + kMaxNumberChars + channels_.size() * (kMaxNumberChars + 1) + 1;
  std::string text(header.size() + frames * perFrame, '\0');
  char* p = std::copy(header.begin(), header.end(), text.data());
  char* const end = text.data() + text.size();
  for (std::size_t i = 0; i < frames; ++i) {
    p = std::copy(mask.begin(), mask.end(), p);
    p = std::to_chars(p, end, i).ptr;
    const FapValues& values = animation_.frames[i];
    for (const int c : channels_) {
      *p++ = ' ';
      p = std::to_chars(p, end,
                        whole(values[static_cast<std::size_t>(c)], isTearChannel(fapNumber(c))))
              .ptr;
    }
    *p++ = '\n';
  }
  text.resize(static_cast<std::size_t>(p - text.data()));

  if (nonFinite_ > 0)
    warn(std::to_string(nonFinite_) + " values that were not finite are written as 0");
  if (clamped_ > 0) {
    warn(std::to_string(clamped_) +
         " values out of range are clamped (FAPs to +-2147483647, tears to 0.." +
         std::to_string(kMaxTearParticles) + ")");
  }
  return text;
}

long TextWriter::fps() {
  const double fps = animation_.fps;
  const long written = std::isfinite(fps) ? std::lround(std::clamp(fps, 1.0, double(kMaxFps))) : 1;
  if (written != fps) {
    warn("the frame rate " + formatNumber(fps) + " is written as " + std::to_string(written) +
         ": the portable profile has whole frame rates from 1 to " + std::to_string(kMaxFps));
  }
  return written;
}

void TextWriter::chooseChannels() {
  const ChannelMask used = animation_.usedChannels();
  const bool tears = animation_.hasTears();
  if (tears && !options_.strict) maskTokens_ = kChannelCount;
  if (tears && options_.strict) warn("strict: the tear channels 69 and 70 are not written");

  bool highLevel = used.test(channelIndex(1)) || used.test(channelIndex(2));
  for (const HighLevelFrame& frame : animation_.highLevel)
    highLevel = highLevel || frame != HighLevelFrame{};
  if (highLevel) {
    warn(
        "FAP 1 (viseme) and FAP 2 (expression) are not written: players disagree on their "
        "syntax, so the portable profile leaves them to the low-level FAPs");
  }

  for (int c = channelIndex(3); c < maskTokens_; ++c)
    if (used.test(static_cast<std::size_t>(c))) channels_.push_back(c);
}

std::string TextWriter::maskLine() const {
  std::string line;
  line.reserve(static_cast<std::size_t>(maskTokens_) * 2 + 1);
  std::size_t next = 0;
  for (int c = 0; c < maskTokens_; ++c) {
    const bool set = next < channels_.size() && channels_[next] == c;
    if (set) ++next;
    line += set ? "1 " : "0 ";  // a space after every token, as the original writers do
  }
  line += '\n';
  return line;
}

int TextWriter::whole(float value, bool tear) {
  if (!std::isfinite(value)) {
    ++nonFinite_;
    return 0;
  }
  const double low = tear ? 0.0 : -kMaxWrittenValue;
  const double high = tear ? double(kMaxTearParticles) : kMaxWrittenValue;
  const double v = std::clamp(static_cast<double>(value), low, high);
  if (v != value) ++clamped_;
  // Same as std::lround for every float (v +- 0.5 is exact in double), without a libm call per
  // value; the result is an integer, so it never prints as "-0".
  return static_cast<int>(v < 0 ? v - 0.5 : v + 0.5);
}

}  // namespace

std::string FapWriter::toText(const FapAnimation& animation, const FapWriteOptions& options,
                              Warnings* warnings) {
  return TextWriter(animation, options, warnings, std::string()).write();
}

void FapWriter::save(const FapAnimation& animation, const std::string& path,
                     const FapWriteOptions& options, Warnings* warnings) {
  const std::string text = TextWriter(animation, options, warnings, path).write();
  saveAtomically(path, text);
}

}  // namespace lacrima::inline common
