#include "FapTokenizer.h"

#include <array>
#include <charconv>
#include <cmath>
#include <limits>

namespace lacrima::inline common::detail {

namespace {

enum ByteClass : unsigned char { kText, kBlank, kControl };

constexpr std::array<unsigned char, 256> makeByteClasses() {
  std::array<unsigned char, 256> classes{};
  for (int c = 0; c < 0x20; ++c) classes[c] = kControl;
  classes[0x7f] = kControl;
  for (unsigned char c : {' ', '\t', '\r', '\v', '\f'}) classes[c] = kBlank;
  return classes;  // bytes >= 0x80 are text: names and comments may be UTF-8
}

constexpr std::array<unsigned char, 256> kByteClass = makeByteClasses();

unsigned char byteClass(char c) { return kByteClass[static_cast<unsigned char>(c)]; }

bool isDigit(char c) { return c >= '0' && c <= '9'; }

}  // namespace

std::string_view TokenCursor::next() {
  while (p_ < end_ && byteClass(*p_) == kBlank) ++p_;
  if (p_ == end_ || byteClass(*p_) != kText || *p_ == '#') return {};
  const char* start = p_;
  while (++p_ < end_ && byteClass(*p_) == kText) {
  }
  return {start, static_cast<std::size_t>(p_ - start)};
}

NumberStatus TokenCursor::nextNumber(std::string_view& token, double& value) {
  while (p_ < end_ && byteClass(*p_) == kBlank) ++p_;
  const char* const start = p_;
  const char* q = start;
  const bool negative = q < end_ && *q == '-';
  if (negative) ++q;
  const char* const digits = q;
  long whole = 0;
  // At most 9 digits: no overflow, and exact in float.
  while (q < end_ && q - digits < 10 && isDigit(*q)) whole = whole * 10 + (*q++ - '0');
  if (q != digits && q - digits < 10 && (q == end_ || byteClass(*q) == kBlank)) {
    p_ = q;
    token = {start, static_cast<std::size_t>(q - start)};
    value = static_cast<double>(negative ? -whole : whole);
    return NumberStatus::Ok;
  }
  token = next();  // anything else: the general syntax
  return token.empty() ? NumberStatus::NotANumber : parseNumber(token, value);
}

long TokenCursor::controlByteInRest() const {
  for (const char* p = p_; p < end_; ++p)
    if (byteClass(*p) == kControl) return p - begin_;
  return -1;
}

long tokenizeLine(std::string_view line, std::vector<std::string_view>& tokens) {
  tokens.clear();
  TokenCursor cursor(line);
  for (std::string_view token = cursor.next(); !token.empty(); token = cursor.next())
    tokens.push_back(token);
  return cursor.controlByteInRest();
}

NumberStatus parseNumber(std::string_view token, double& value) {
  const char* p = token.data();
  const char* end = p + token.size();
  if (p < end && *p == '+') {
    ++p;
    if (p < end && *p == '-') return NumberStatus::NotANumber;
  }
  if (p == end) return NumberStatus::NotANumber;

  // Almost every value in real files is a short integer: read those without from_chars.
  {
    const bool negative = *p == '-';
    const char* q = p + (negative ? 1 : 0);
    if (q < end && end - q <= 9) {
      long whole = 0;
      const char* d = q;
      for (; d < end && isDigit(*d); ++d) whole = whole * 10 + (*d - '0');
      if (d == end) {
        value = static_cast<double>(negative ? -whole : whole);
        return NumberStatus::Ok;
      }
    }
  }

  double parsed = 0;
  const auto [ptr, ec] = std::from_chars(p, end, parsed, std::chars_format::general);
  if (ec == std::errc::result_out_of_range) return NumberStatus::OutOfRange;
  if (ec != std::errc() || ptr != end) return NumberStatus::NotANumber;
  if (!std::isfinite(parsed)) return NumberStatus::NotFinite;
  if (std::fabs(parsed) > std::numeric_limits<float>::max()) return NumberStatus::OutOfRange;
  value = parsed;
  return NumberStatus::Ok;
}

WholeStatus parseDigits(std::string_view token, std::int64_t cap, std::int64_t& value) {
  std::size_t i = 0;
  bool negative = false;
  if (i < token.size() && (token[i] == '+' || token[i] == '-')) negative = token[i++] == '-';
  if (i == token.size()) return WholeStatus::NotWhole;
  std::int64_t result = 0;
  for (; i < token.size(); ++i) {
    if (!isDigit(token[i])) return WholeStatus::NotWhole;
    if (result <= cap) result = result * 10 + (token[i] - '0');  // stops growing past cap
  }
  if (negative) return result == 0 ? (value = 0, WholeStatus::Ok) : WholeStatus::Negative;
  value = result > cap ? cap + 1 : result;
  return WholeStatus::Ok;
}

std::string quoteToken(std::string_view token) {
  constexpr std::size_t kShown = 20;
  std::size_t cut = token.size();
  if (cut > kShown) {
    cut = kShown;
    // Do not split a UTF-8 sequence: back up over continuation bytes.
    while (cut > 0 && (static_cast<unsigned char>(token[cut]) & 0xC0) == 0x80) --cut;
  }
  std::string quoted;
  quoted.reserve(cut + 5);
  quoted.append(1, '\'').append(token.substr(0, cut));
  if (cut < token.size()) quoted.append("...");
  quoted.append(1, '\'');
  return quoted;
}

}  // namespace lacrima::inline common::detail
