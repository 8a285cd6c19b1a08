#pragma once
// Tokens and numbers of a .fap line. Private to lacrima_common (used by FapReader).
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace lacrima::inline common::detail {

enum class NumberStatus { Ok, NotANumber, NotFinite, OutOfRange };

// Walks the tokens of one line: blanks (space, tab, CR, VT, FF) separate them, and a token
// that starts with '#' ends the line's tokens. Allocates nothing, for the per-frame hot path.
class TokenCursor {
 public:
  explicit TokenCursor(std::string_view line)
      : begin_(line.data()), p_(begin_), end_(begin_ + line.size()) {}

  // The next token, or an empty view when no plain token follows: at the end of the line, at a
  // '#' token, or at a control byte (see stoppedEarly()).
  std::string_view next();

  // next(), read as a number (see parseNumber). The usual token, a short integer, is read in
  // the same pass that finds its end.
  NumberStatus nextNumber(std::string_view& token, double& value);

  // True when next() stopped before the end of the line, at '#' or at a control byte.
  bool stoppedEarly() const { return p_ != end_; }

  // Offset (0-based) of the first control byte other than a blank -- a sign of binary input --
  // from where next() stopped to the end of the line, comment included; -1 when there is none.
  long controlByteInRest() const;

 private:
  const char* begin_;
  const char* p_;
  const char* end_;
};

// All tokens of `line`. Returns controlByteInRest() of the line: when it is >= 0 the tokens are
// incomplete and must not be used.
long tokenizeLine(std::string_view line, std::vector<std::string_view>& tokens);

// A decimal in std::from_chars' general syntax, with an optional leading '+'. Finite only, and
// within float range (values are stored as float).
NumberStatus parseNumber(std::string_view token, double& value);

// A whole number written with digits only (optional leading '+'). Values above `cap` come back
// as cap + 1, so callers can reject them without overflow.
enum class WholeStatus { Ok, NotWhole, Negative };
WholeStatus parseDigits(std::string_view token, std::int64_t cap, std::int64_t& value);

// The token for a message: quoted, cut to about 20 characters.
std::string quoteToken(std::string_view token);

}  // namespace lacrima::inline common::detail
