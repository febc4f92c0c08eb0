#pragma once
#include <map>
#include <memory>
#include <string>

#include "core/OpenSeesError.h"

namespace beamsolid {

// Objects of one kind keyed by tag, with OpenSees-style errors for a
// duplicate or a missing tag.
template <class T>
class TaggedStore {
 public:
  explicit TaggedStore(std::string kind) : kind_(std::move(kind)) {}

  const std::string& kind() const { return kind_; }

  void add(int tag, std::shared_ptr<T> item, const std::string& context) {
    if (items_.count(tag))
      throw OpenSeesError(context + ": " + kind_ + " with tag " + std::to_string(tag) + " already exists");
    items_.emplace(tag, std::move(item));
  }
  T* find(int tag) const {
    auto it = items_.find(tag);
    return it == items_.end() ? nullptr : it->second.get();
  }
  std::shared_ptr<T> shared(int tag, const std::string& context) const {
    auto it = items_.find(tag);
    if (it == items_.end()) throw missing(tag, context);
    return it->second;
  }
  T& get(int tag, const std::string& context) const { return *shared(tag, context); }
  bool remove(int tag) { return items_.erase(tag) > 0; }
  void clear() { items_.clear(); }
  std::size_t size() const { return items_.size(); }
  auto begin() const { return items_.begin(); }
  auto end() const { return items_.end(); }

 private:
  OpenSeesError missing(int tag, const std::string& context) const {
    return OpenSeesError(context + ": " + kind_ + " " + std::to_string(tag) + " does not exist");
  }
  std::string kind_;
  std::map<int, std::shared_ptr<T>> items_;
};

}  // namespace beamsolid
