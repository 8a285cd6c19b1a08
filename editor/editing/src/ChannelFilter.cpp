#include <lacrima/editing/ChannelFilter.h>

#include <algorithm>
#include <cctype>
#include <charconv>

namespace lacrima::editing {
namespace {

std::string normalised(std::string_view text) {
  std::string out;
  for (char c : text)
    out += c == ' ' ? '_' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

bool parseInt(std::string_view text, int& out) {
  if (text.empty()) return false;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), out);
  return error == std::errc() && end == text.data() + text.size();
}

bool hasSide(const std::string& name, char side) {
  const std::string inner = std::string("_") + side + "_";
  const std::string tail = std::string("_") + side;
  return name.find(inner) != std::string::npos ||
         (name.size() > 2 && name.compare(name.size() - 2, 2, tail) == 0);
}

}  // namespace

ChannelFilter::ChannelFilter(std::string_view text) {
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    const std::string_view part = text.substr(start, comma - start);
    std::vector<Word> words;
    std::size_t i = 0;
    while (i < part.size()) {
      while (i < part.size() && std::isspace(static_cast<unsigned char>(part[i]))) ++i;
      std::size_t j = i;
      while (j < part.size() && !std::isspace(static_cast<unsigned char>(part[j]))) ++j;
      if (j > i) {
        const std::string_view token = part.substr(i, j - i);
        Word word;
        const std::size_t dash = token.find('-');
        int a = 0;
        int b = 0;
        if (parseInt(token, a)) {
          word.from = word.to = a;
        } else if (dash != std::string_view::npos && parseInt(token.substr(0, dash), a) &&
                   parseInt(token.substr(dash + 1), b)) {
          word.from = std::min(a, b);
          word.to = std::max(a, b);
        } else {
          word.text = normalised(token);
          word.groups =
              std::none_of(fapTable().begin(), fapTable().end(), [&](const FapInfo& info) {
                return normalised(info.name).find(word.text) != std::string::npos;
              });
        }
        words.push_back(word);
      }
      i = j;
    }
    if (!words.empty()) alternatives_.push_back(std::move(words));
    start = comma + 1;
  }
}

bool ChannelFilter::matches(const FapInfo& info) const {
  if (alternatives_.empty()) return true;
  const std::string name = normalised(info.name);
  const std::string group = normalised(toString(info.group));
  // A word no name holds may be one the names abbreviate ("inner" for the _i_ of
  // raise_l_i_eyebrow): the descriptions spell those out.
  const std::string description = normalised(info.description);
  for (const auto& words : alternatives_) {
    const bool all = std::all_of(words.begin(), words.end(), [&](const Word& w) {
      if (w.from <= w.to) return info.number >= w.from && info.number <= w.to;
      if (w.text == "left") return hasSide(name, 'l');
      if (w.text == "right") return hasSide(name, 'r');
      if (!w.groups) return name.find(w.text) != std::string::npos;
      return group.find(w.text) != std::string::npos ||
             description.find(w.text) != std::string::npos;
    });
    if (all) return true;
  }
  return false;
}

ChannelMask ChannelFilter::matching() const {
  ChannelMask mask;
  for (const FapInfo& info : fapTable())
    if (matches(info)) mask.set(channelIndex(info.number));
  return mask;
}

}  // namespace lacrima::editing
