#pragma once
// The way from the top of a JSON document to one value, such as presets[3].values.open_jaw:
// what an error names so that a person can find the value, and what JsonPathLocator.h follows
// through the text to give its line and column.
#include <memory>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace lacrima::inline common {

class JsonPath {
 public:
  // A member name or an array index.
  using Step = std::variant<std::string, int>;

  JsonPath() = default;                               // the top-level value
  JsonPath operator/(std::string_view member) const;  // path.member
  JsonPath operator/(int index) const;                // path[index]

  bool empty() const { return last_ == nullptr; }
  // Without its last step; the top level is its own parent.
  JsonPath parent() const;
  // Precondition: !empty().
  const Step& last() const { return last_->step; }
  // Outermost first.
  std::vector<Step> steps() const;
  // "presets[3].values.open_jaw"; member names that are not plain identifiers are quoted.
  std::string toString() const;

 private:
  // Readers extend a path at every value they visit and print one only on an error, so a path
  // shares its parent's steps: extending it is one small allocation at any depth.
  struct Node {
    std::shared_ptr<const Node> parent;
    Step step;
  };
  explicit JsonPath(std::shared_ptr<const Node> last) : last_(std::move(last)) {}

  std::shared_ptr<const Node> last_;
};

}  // namespace lacrima::inline common
