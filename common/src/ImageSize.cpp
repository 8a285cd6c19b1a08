#include <lacrima/common/ImageSize.h>

#include <charconv>
#include <optional>

namespace lacrima::inline common {

namespace {

std::optional<int> wholeNumber(std::string_view digits) {
  int value = 0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (digits.empty() || ec != std::errc() || end != digits.data() + digits.size())
    return std::nullopt;
  return value;
}

}  // namespace

ParsedImageSize parseImageSize(std::string_view text) {
  const std::size_t x = text.find_first_of("xX");
  const std::optional<int> width =
      x == std::string_view::npos ? std::nullopt : wholeNumber(text.substr(0, x));
  const std::optional<int> height =
      x == std::string_view::npos ? std::nullopt : wholeNumber(text.substr(x + 1));
  if (width && height && isImageSizeInBounds(QSize(*width, *height)))
    return {QSize(*width, *height), {}};
  return {QSize(), "expected WIDTHxHEIGHT with each side " + std::to_string(kMinImageSide) +
                       " to " + std::to_string(kMaxImageSide) + ", e.g. 1280x720, not '" +
                       std::string(text) + "'"};
}

}  // namespace lacrima::inline common
