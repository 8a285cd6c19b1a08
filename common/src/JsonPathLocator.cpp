#include <lacrima/common/JsonPathLocator.h>

#include <cctype>
#include <optional>

namespace lacrima::inline common {
namespace {

// Walks valid JSON text. Every function starts on the first character of what it reads and
// leaves `at` just past it.
class Scanner {
 public:
  explicit Scanner(std::string_view text) : text_(text) {}

  std::optional<std::size_t> find(const JsonPath& path) {
    skipSpace();
    return findIn(path.steps(), 0);
  }

 private:
  std::optional<std::size_t> findIn(const std::vector<JsonPath::Step>& steps, std::size_t depth) {
    if (depth == steps.size()) return at_;
    if (const auto* member = std::get_if<std::string>(&steps[depth])) {
      if (peek() != '{') return std::nullopt;
      ++at_;
      std::optional<std::size_t> foundKey;
      std::size_t foundValue = 0;
      skipSpace();
      while (peek() == '"') {
        const std::size_t keyStart = at_;
        const std::string key = readString();
        skipSpace();
        ++at_;  // ':'
        skipSpace();
        if (key == *member) {  // remember the last match: duplicates resolve to the last
          foundKey = keyStart;
          foundValue = at_;
        }
        skipValue();
        skipSpace();
        if (peek() == ',') {
          ++at_;
          skipSpace();
        }
      }
      if (!foundKey) return std::nullopt;
      if (depth + 1 == steps.size()) return foundKey;
      at_ = foundValue;
      return findIn(steps, depth + 1);
    }
    const int wanted = std::get<int>(steps[depth]);
    if (peek() != '[') return std::nullopt;
    ++at_;
    skipSpace();
    for (int index = 0; peek() != ']' && at_ < text_.size(); ++index) {
      if (index == wanted) return findIn(steps, depth + 1);
      skipValue();
      skipSpace();
      if (peek() == ',') {
        ++at_;
        skipSpace();
      }
    }
    return std::nullopt;
  }

  char peek() const { return at_ < text_.size() ? text_[at_] : '\0'; }

  void skipSpace() {
    while (at_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[at_]))) ++at_;
  }

  // The key as QJsonDocument decodes it, so that it compares equal to the path's member name.
  std::string readString() {
    std::string out;
    ++at_;  // opening quote
    while (at_ < text_.size() && text_[at_] != '"') {
      if (text_[at_] != '\\' || at_ + 1 >= text_.size()) {
        out += text_[at_++];
        continue;
      }
      const char c = text_[at_ + 1];
      at_ += 2;
      switch (c) {
        case 'b':
          out += '\b';
          break;
        case 'f':
          out += '\f';
          break;
        case 'n':
          out += '\n';
          break;
        case 'r':
          out += '\r';
          break;
        case 't':
          out += '\t';
          break;
        case 'u':
          appendUtf8(readCodePoint(), out);
          break;
        default:
          out += c;  // \" \\ \/
      }
    }
    ++at_;  // closing quote
    return out;
  }

  // The code point of a \uXXXX escape whose "\u" was read, joining a surrogate pair.
  char32_t readCodePoint() {
    const char32_t unit = readHex4();
    if (unit >= 0xD800 && unit < 0xDC00 && text_.substr(at_, 2) == "\\u") {
      at_ += 2;
      const char32_t low = readHex4();
      return 0x10000 + ((unit - 0xD800) << 10) + (low - 0xDC00);
    }
    return unit;
  }

  char32_t readHex4() {
    char32_t value = 0;
    for (int i = 0; i < 4 && at_ < text_.size(); ++i, ++at_) {
      const char c = text_[at_];
      const int digit = c <= '9' ? c - '0' : (c | 0x20) - 'a' + 10;
      value = value * 16 + static_cast<char32_t>(digit);
    }
    return value;
  }

  static void appendUtf8(char32_t c, std::string& out) {
    const auto byte = [&](char32_t bits) { out += static_cast<char>(bits); };
    if (c < 0x80) {
      byte(c);
    } else if (c < 0x800) {
      byte(0xC0 | (c >> 6));
      byte(0x80 | (c & 0x3F));
    } else if (c < 0x10000) {
      byte(0xE0 | (c >> 12));
      byte(0x80 | ((c >> 6) & 0x3F));
      byte(0x80 | (c & 0x3F));
    } else {
      byte(0xF0 | (c >> 18));
      byte(0x80 | ((c >> 12) & 0x3F));
      byte(0x80 | ((c >> 6) & 0x3F));
      byte(0x80 | (c & 0x3F));
    }
  }

  void skipValue() {
    const char c = peek();
    if (c == '"') {
      readString();
    } else if (c == '{' || c == '[') {
      int depth = 0;
      while (at_ < text_.size()) {
        const char d = text_[at_];
        if (d == '"') {
          readString();
          continue;
        }
        if (d == '{' || d == '[') ++depth;
        if (d == '}' || d == ']') {
          if (--depth == 0) {
            ++at_;
            return;
          }
        }
        ++at_;
      }
    } else {
      while (at_ < text_.size() && text_[at_] != ',' && text_[at_] != '}' && text_[at_] != ']' &&
             !std::isspace(static_cast<unsigned char>(text_[at_])))
        ++at_;
    }
  }

  std::string_view text_;
  std::size_t at_ = 0;
};

}  // namespace

SourceLocation locateJsonPath(std::string_view json, const JsonPath& path,
                              const std::string& file) {
  const std::optional<std::size_t> offset = Scanner(json).find(path);
  if (!offset) return {file, 0, 0};
  return locationInText(json, *offset, file);
}

}  // namespace lacrima::inline common
