#pragma once
// A small named registry: the one place that looks a name up, words the "unknown X; known: …"
// message and lists the names for help texts. Models, metrics, procedures and distribution
// families each keep one, so the CLI, JSON readers and Python name them the same way.
#include <algorithm>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "brdfkit/core/error.h"

namespace brdfkit {

template <class T> class Registry {
 public:
  // kind: what an entry is called in messages ("model", "metric", "procedure", …).
  explicit Registry(std::string kind) : kind_(std::move(kind)) {}

  // Entries keep the order they were added in: listings and help texts show that order.
  Registry& add(std::string name, T value) {
    names_.push_back(std::move(name));
    values_.push_back(std::move(value));
    return *this;
  }

  // The entry called `name`, or nullptr.
  const T* find(std::string_view name) const {
    auto it = std::find(names_.begin(), names_.end(), name);
    return it == names_.end() ? nullptr : &values_[std::size_t(it - names_.begin())];
  }
  // The entry called `name`; InputError "<kind> 'name': unknown; known <kind>s: a, b, …" otherwise.
  const T& get(std::string_view name) const {
    if (const T* v = find(name)) return *v;
    throw unknown(name);
  }
  bool contains(std::string_view name) const { return find(name) != nullptr; }

  const std::vector<std::string>& names() const { return names_; }
  // The entries in order (iterating a registry visits them).
  const std::vector<T>& values() const { return values_; }
  auto begin() const { return values_.begin(); }
  auto end() const { return values_.end(); }
  std::size_t size() const { return values_.size(); }
  // "a, b, c": for help texts and messages.
  std::string listing(std::string_view separator = ", ") const {
    std::string out;
    for (const std::string& n : names_) out += (out.empty() ? "" : std::string(separator)) + n;
    return out;
  }
  const std::string& kind() const { return kind_; }

  // The error `get` throws, for callers that resolve names in more ways than one (model sums).
  InputError unknown(std::string_view name, std::string_view note = "") const {
    return InputError(kind_ + " '" + std::string(name) + "'",
                      "unknown; known " + kind_ + "s: " + listing() + std::string(note));
  }
  // The same message for a name given as a setting (FitSettings::metric, BatchSettings::models …).
  SettingError unknown_setting(const std::string& setting, std::string_view name) const {
    return SettingError(setting, "unknown " + kind_ + " '" + std::string(name) + "'; known " + kind_ + "s: " + listing());
  }

 private:
  std::string kind_;
  std::vector<std::string> names_;  // parallel to values_
  std::vector<T> values_;
};

}  // namespace brdfkit
