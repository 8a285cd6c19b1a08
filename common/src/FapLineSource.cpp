#include "FapLineSource.h"

#include <lacrima/common/Diagnostics.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

namespace lacrima::inline common::detail {

LineSource::LineSource(std::string_view text, const std::string& displayName,
                       std::size_t maxLineLength)
    : displayName_(displayName), maxLineLength_(maxLineLength), window_(text), atEnd_(true) {}

LineSource::LineSource(std::FILE* file, const std::string& displayName, std::size_t maxLineLength)
    : displayName_(displayName),
      maxLineLength_(maxLineLength),
      file_(file),
      // A partial line carried over is at most maxLineLength bytes (longer ones are rejected),
      // so every refill has room for a whole chunk.
      buffer_(maxLineLength + 1 + kChunkSize) {
  // Chunks are large: stdio's own buffer would only add a copy and split each read in two.
  std::setvbuf(file_, nullptr, _IONBF, 0);
}

bool LineSource::next(std::string_view& line) {
  for (;;) {
    // Search no further than one byte past the limit: an 8 MB line costs 64 KiB of scanning.
    const std::size_t limit = std::min(window_.size(), maxLineLength_ + 1);
    const void* newline = limit ? std::memchr(window_.data(), '\n', limit) : nullptr;
    if (newline) {
      const auto length =
          static_cast<std::size_t>(static_cast<const char*>(newline) - window_.data());
      line = window_.substr(0, length);
      window_.remove_prefix(length + 1);
      ++lineNumber_;
      sawInput_ = true;
      return true;
    }
    if (window_.size() > maxLineLength_) {
      throw FileError({displayName_, lineNumber_ + 1, static_cast<int>(maxLineLength_) + 1},
                      "line is longer than " + std::to_string(maxLineLength_) +
                          " bytes: not a .fap file (a real value line is a few KiB)");
    }
    if (!refill()) {
      if (window_.empty()) return false;
      line = window_;  // last line without a final newline
      window_ = {};
      ++lineNumber_;
      sawInput_ = true;
      return true;
    }
  }
}

bool LineSource::refill() {
  if (atEnd_) return false;
  char* base = buffer_.data();
  if (!window_.empty() && window_.data() != base)
    std::memmove(base, window_.data(), window_.size());
  const std::size_t kept = window_.size();
  const std::size_t got = std::fread(base + kept, 1, buffer_.size() - kept, file_);
  if (got == 0) {
    atEnd_ = true;
    if (std::ferror(file_)) {
      throw FileError({displayName_, 0, 0}, std::string("cannot read: ") + std::strerror(errno));
    }
    window_ = std::string_view(base, kept);
    return false;
  }
  window_ = std::string_view(base, kept + got);
  return true;
}

}  // namespace lacrima::inline common::detail
