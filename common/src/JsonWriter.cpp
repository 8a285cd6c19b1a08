#include <lacrima/common/JsonWriter.h>

#include <QString>

#include <array>
#include <charconv>
#include <cmath>

namespace lacrima::inline common {

std::string formatJsonNumber(double value) {
  std::array<char, 400> buffer{};
  char* const first = buffer.data();
  char* const last = first + buffer.size();
  const double magnitude = std::abs(value);
  const bool plain = magnitude == 0.0 || (magnitude >= 1e-5 && magnitude < 1e16);
  const auto result = plain ? std::to_chars(first, last, value, std::chars_format::fixed)
                            : std::to_chars(first, last, value);
  return std::string(first, result.ptr);
}

void JsonWriter::key(std::string_view name) {
  separate();
  appendString(name);
  text_ += ": ";
  afterKey_ = true;
}

void JsonWriter::string(std::string_view value) {
  separate();
  appendString(value);
}

void JsonWriter::number(double value) {
  separate();
  appendNumber(value);
}

void JsonWriter::integer(long long value) {
  separate();
  text_ += std::to_string(value);
}

void JsonWriter::boolean(bool value) {
  separate();
  text_ += value ? "true" : "false";
}

void JsonWriter::null() {
  separate();
  text_ += "null";
}

void JsonWriter::numberRow(std::span<const double> values) {
  separate();
  text_ += '[';
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i > 0) text_ += ", ";
    appendNumber(values[i]);
  }
  text_ += ']';
}

std::string JsonWriter::finish() && { return std::move(text_) + '\n'; }

// Puts the comma and line break before a value, unless it follows its key.
void JsonWriter::separate() {
  if (afterKey_) {
    afterKey_ = false;
    return;
  }
  if (emptyStack_.empty()) return;
  if (!emptyStack_.back()) text_ += layout_ == Layout::Indented ? "," : ", ";
  emptyStack_.back() = false;
  newline();
}

void JsonWriter::open(char bracket) {
  separate();
  text_ += bracket;
  emptyStack_.push_back(true);
}

void JsonWriter::close(char bracket) {
  const bool empty = emptyStack_.back();
  emptyStack_.pop_back();
  if (!empty) newline();
  text_ += bracket;
}

void JsonWriter::newline() {
  if (layout_ == Layout::Compact) return;
  text_ += '\n';
  text_.append(2 * emptyStack_.size(), ' ');
}

void JsonWriter::appendNumber(double value) {
  // null makes a reader name the field instead of guessing a value.
  text_ += std::isfinite(value) ? formatJsonNumber(value) : "null";
}

void JsonWriter::appendString(std::string_view value) {
  // Round-trip through QString so invalid UTF-8 becomes U+FFFD instead of a broken file.
  const QByteArray utf8 =
      QString::fromUtf8(value.data(), static_cast<qsizetype>(value.size())).toUtf8();
  text_ += '"';
  for (const char c : utf8) appendEscaped(c);
  text_ += '"';
}

void JsonWriter::appendEscaped(char c) {
  switch (c) {
    case '"':
      text_ += "\\\"";
      return;
    case '\\':
      text_ += "\\\\";
      return;
    case '\n':
      text_ += "\\n";
      return;
    case '\r':
      text_ += "\\r";
      return;
    case '\t':
      text_ += "\\t";
      return;
    default:
      break;
  }
  if (static_cast<unsigned char>(c) < 0x20) {
    constexpr char kHex[] = "0123456789abcdef";
    text_ += "\\u00";
    text_ += kHex[(c >> 4) & 0xf];
    text_ += kHex[c & 0xf];
    return;
  }
  text_ += c;
}

}  // namespace lacrima::inline common
