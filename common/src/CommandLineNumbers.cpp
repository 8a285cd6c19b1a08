#include <lacrima/common/CommandLineNumbers.h>
#include <lacrima/common/JsonWriter.h>

#include <charconv>
#include <cmath>

namespace lacrima::inline common {

namespace {

// The value when all of `text` is one number of type T in [low, high].
template <typename T>
std::optional<T> readAll(std::string_view text, T low, T high) {
  T value{};
  const char* end = text.data() + text.size();
  const auto [stop, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ec != std::errc() || stop != end) return std::nullopt;
  if constexpr (std::is_floating_point_v<T>) {
    if (!std::isfinite(value)) return std::nullopt;
  }
  if (value < low || value > high) return std::nullopt;
  return value;
}

template <typename T>
std::optional<T> readOption(std::string_view option, std::string_view what, std::string_view text,
                            T low, T high, std::string& error) {
  if (const std::optional<T> value = readAll(text, low, high)) return value;
  error = std::string(option) + ": expected " + std::string(what) + " from " +
          formatJsonNumber(low) + " to " + formatJsonNumber(high) + ", not '" + std::string(text) +
          "'";
  return std::nullopt;
}

}  // namespace

std::optional<double> readNumberOption(std::string_view option, std::string_view what,
                                       std::string_view text, double low, double high,
                                       std::string& error) {
  return readOption(option, what, text, low, high, error);
}

std::optional<int> readWholeNumberOption(std::string_view option, std::string_view what,
                                         std::string_view text, int low, int high,
                                         std::string& error) {
  return readOption(option, what, text, low, high, error);
}

}  // namespace lacrima::inline common
