#include <lacrima/editing/JsonPathLocator.h>

#include <cctype>
#include <optional>

namespace lacrima::editing {
namespace {

bool isIdentifier(std::string_view name) {
  if (name.empty()) return false;
  for (char c : name)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-')) return false;
  return true;
}

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
  std::optional<std::size_t> findIn(const std::vector<std::variant<std::string, int>>& steps,
                                    std::size_t depth) {
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

  // Unescapes the common escapes; \u sequences are kept literally (keys here are ASCII).
  std::string readString() {
    std::string out;
    ++at_;  // opening quote
    while (at_ < text_.size() && text_[at_] != '"') {
      if (text_[at_] == '\\' && at_ + 1 < text_.size()) {
        ++at_;
        const char c = text_[at_];
        out += c == 'n' ? '\n' : c == 't' ? '\t' : c;
      } else {
        out += text_[at_];
      }
      ++at_;
    }
    ++at_;  // closing quote
    return out;
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

JsonPath JsonPath::operator/(std::string_view member) const {
  JsonPath path = *this;
  path.steps_.emplace_back(std::string(member));
  return path;
}

JsonPath JsonPath::operator/(int index) const {
  JsonPath path = *this;
  path.steps_.emplace_back(index);
  return path;
}

std::string JsonPath::toString() const {
  std::string text;
  for (const auto& step : steps_) {
    if (const auto* member = std::get_if<std::string>(&step)) {
      if (isIdentifier(*member)) {
        if (!text.empty()) text += '.';
        text += *member;
      } else {
        if (!text.empty()) text += '.';
        text += '"' + *member + '"';
      }
    } else {
      text += '[' + std::to_string(std::get<int>(step)) + ']';
    }
  }
  return text;
}

SourceLocation locateJsonPath(std::string_view json, const JsonPath& path, const std::string& file) {
  const std::optional<std::size_t> offset = Scanner(json).find(path);
  if (!offset) return {file, 0, 0};
  int line = 1;
  int column = 1;
  for (std::size_t i = 0; i < *offset && i < json.size(); ++i) {
    if (json[i] == '\n') {
      ++line;
      column = 1;
    } else if ((static_cast<unsigned char>(json[i]) & 0xC0) != 0x80) {
      ++column;
    }
  }
  return {file, line, column};
}

}  // namespace lacrima::editing
