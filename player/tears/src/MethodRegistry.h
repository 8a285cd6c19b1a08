#pragma once
// One family's registry (TearMethods.h): each method's description and the function that
// makes it from its parameter values and what the simulation gives every method of the family
// (`Context`). The built-in methods are listed once, in the family's registration file; add()
// lets a test build register more before any simulation starts (it is not synchronised with
// simulations making methods on other threads).
#include <lacrima/tears/TearMethods.h>

#include <deque>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace lacrima::tears {

template <typename Method, typename... Context>
class MethodRegistry {
 public:
  using Creator = std::function<std::unique_ptr<Method>(const MethodValues&, Context...)>;
  struct Entry {
    MethodInfo info;
    Creator create;
  };

  MethodRegistry(MethodFamily family, std::vector<Entry> methods) : family_(family) {
    for (Entry& entry : methods) add(std::move(entry));
  }

  // Throws std::invalid_argument when the key is taken or empty.
  void add(Entry entry) {
    if (entry.info.key.empty() || !entry.create)
      throw std::invalid_argument(std::string(familyName(family_)) +
                                  ": a method needs a key and a creator");
    if (find(entry.info.key))
      throw std::invalid_argument(std::string(familyName(family_)) + " \"" + entry.info.key +
                                  "\" is registered already");
    entries_.push_back(std::move(entry));  // a deque: earlier entries stay where they are
  }

  const Entry* find(std::string_view key) const {
    for (const Entry& entry : entries_)
      if (entry.info.key == key) return &entry;
    return nullptr;
  }

  // Throws std::invalid_argument naming the known keys for an unknown one, or for a bad
  // parameter (MethodValues).
  std::unique_ptr<Method> create(const MethodChoice& choice, Context... context) const {
    const Entry* entry = find(choice.key);
    if (!entry) throw std::invalid_argument(unknownMessage(choice.key));
    return entry->create(MethodValues(entry->info, choice), context...);
  }

  std::vector<MethodInfo> infos() const {
    std::vector<MethodInfo> result;
    for (const Entry& entry : entries_) result.push_back(entry.info);
    return result;
  }

  std::string unknownMessage(std::string_view key) const {
    return "unknown " + std::string(familyName(family_)) + " \"" + std::string(key) +
           "\"; expected " + knownKeys(family_);
  }

 private:
  MethodFamily family_;
  std::deque<Entry> entries_;  // registration order
};

}  // namespace lacrima::tears
