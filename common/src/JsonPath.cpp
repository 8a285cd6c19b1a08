#include <lacrima/common/JsonPath.h>

#include <algorithm>
#include <cctype>

namespace lacrima::inline common {
namespace {

bool isIdentifier(std::string_view name) {
  return !name.empty() && std::all_of(name.begin(), name.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
  });
}

}  // namespace

JsonPath JsonPath::operator/(std::string_view member) const {
  return JsonPath(std::make_shared<const Node>(Node{last_, std::string(member)}));
}

JsonPath JsonPath::operator/(int index) const {
  return JsonPath(std::make_shared<const Node>(Node{last_, index}));
}

JsonPath JsonPath::parent() const { return empty() ? *this : JsonPath(last_->parent); }

std::vector<JsonPath::Step> JsonPath::steps() const {
  std::vector<Step> steps;
  for (const Node* node = last_.get(); node; node = node->parent.get()) steps.push_back(node->step);
  std::reverse(steps.begin(), steps.end());
  return steps;
}

std::string JsonPath::toString() const {
  std::string text;
  for (const Step& step : steps()) {
    if (const auto* member = std::get_if<std::string>(&step)) {
      if (!text.empty()) text += '.';
      text += isIdentifier(*member) ? *member : '"' + *member + '"';
    } else {
      text += '[' + std::to_string(std::get<int>(step)) + ']';
    }
  }
  return text;
}

}  // namespace lacrima::inline common
