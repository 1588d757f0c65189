#pragma once
// Contract: a process's last few results of a pure, costly function, shared read-only: get(key, make) returns
// the value kept for an equal key, or calls make() (outside the lock, so a slow build blocks no other key's
// lookups; two threads asking for the same new key at once may both make it: the first kept is returned to
// both) and keeps it, dropping the least recently made past `Capacity`. Thread-safe. make() may throw; nothing
// is kept then. A process-wide instance is best never destroyed (`static auto& c = *new RecentCache<...>`):
// a detached thread may still be making a value when the process exits.
#include <cstddef>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <utility>

namespace hp {
template <typename Key, typename Value, std::size_t Capacity>
class RecentCache {
 public:
  template <typename Make>
  std::shared_ptr<const Value> get(const Key& key, Make&& make) {
    if (auto kept = find(key)) return kept;
    auto value = std::make_shared<const Value>(make());
    std::lock_guard<std::mutex> lock(mutex_);
    if (auto kept = findLocked(key)) return kept;  // another thread made it meanwhile
    entries_.emplace_back(key, value);
    if (entries_.size() > Capacity) entries_.pop_front();
    ++made_;
    return value;
  }
  // Values made and kept so far (a diagnostic: whether a get was a hit).
  std::uint64_t made() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return made_;
  }

 private:
  std::shared_ptr<const Value> find(const Key& key) {
    std::lock_guard<std::mutex> lock(mutex_);
    return findLocked(key);
  }
  std::shared_ptr<const Value> findLocked(const Key& key) const {
    for (const auto& [k, v] : entries_)
      if (k == key) return v;
    return nullptr;
  }

  mutable std::mutex mutex_;
  std::uint64_t made_ = 0;  // under mutex_
  std::deque<std::pair<Key, std::shared_ptr<const Value>>> entries_;  // most recently made last
};
}  // namespace hp
