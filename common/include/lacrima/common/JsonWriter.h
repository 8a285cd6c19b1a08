#pragma once
// A streaming JSON writer that keeps fields in the order they are written.
//
// QJsonObject sorts keys alphabetically; Lacrima's documents and benchmark reports are read by
// people, so fields stay in the documented order and channel values in channel order, which also
// keeps the diff of two saves small. Numbers use the shortest text that reads back exactly.
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace lacrima::inline common {

// Shortest decimal text that reads back as exactly `value`: plain digits for the magnitudes
// people type (20000000, not 2e+07), exponents only for the extremes.
std::string formatJsonNumber(double value);

class JsonWriter {
 public:
  // Indented: one value per line, two spaces per level. Compact: one line, ", " between values.
  enum class Layout { Indented, Compact };
  explicit JsonWriter(Layout layout = Layout::Indented) : layout_(layout) {}

  void beginObject() { open('{'); }
  void endObject() { close('}'); }
  void beginArray() { open('['); }
  void endArray() { close(']'); }

  void key(std::string_view name);
  void string(std::string_view value);
  void number(double value);  // NaN and infinities become null: JSON has no such numbers
  void integer(long long value);
  void boolean(bool value);
  void null();
  // A short array of numbers on one line, e.g. a position.
  void numberRow(std::span<const double> values);

  // Convenience for flat reports: key(name) followed by the value.
  void field(std::string_view name, double value) {
    key(name);
    number(value);
  }
  void field(std::string_view name, long long value) {
    key(name);
    integer(value);
  }
  void field(std::string_view name, int value) {
    key(name);
    integer(value);
  }
  void field(std::string_view name, bool value) {
    key(name);
    boolean(value);
  }
  void field(std::string_view name, std::string_view value) {
    key(name);
    string(value);
  }
  void field(std::string_view name, const char* value) {
    key(name);
    string(value);
  }

  // The text, ending in a newline.
  std::string finish() &&;

 private:
  void separate();
  void open(char bracket);
  void close(char bracket);
  void newline();
  void appendNumber(double value);
  void appendString(std::string_view value);
  void appendEscaped(char c);

  Layout layout_;
  std::string text_;
  std::vector<bool> emptyStack_;  // per open container: nothing written in it yet
  bool afterKey_ = false;
};

}  // namespace lacrima::inline common
