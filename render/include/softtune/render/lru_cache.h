#pragma once
// A thread-safe least-recently-used cache bounded by bytes. Values are shared and immutable, so a
// reader keeps its copy alive after eviction.

#include <cstddef>
#include <list>
#include <memory>
#include <mutex>
#include <string>
#include <unordered_map>

namespace softtune::render {

struct CacheStats {
  std::size_t entries = 0;
  std::size_t bytes = 0;       ///< sum of the entries' sizes
  std::size_t capacity = 0;    ///< bytes
  std::size_t hits = 0, misses = 0, evictions = 0;
};

template <typename Value>
class LruCache {
 public:
  explicit LruCache(std::size_t capacity_bytes) : capacity_(capacity_bytes) {}

  /// The value under `key` (now the most recently used), or nullptr.
  std::shared_ptr<const Value> get(const std::string& key) {
    std::lock_guard lock(mutex_);
    auto it = index_.find(key);
    if (it == index_.end()) {
      ++misses_;
      return nullptr;
    }
    ++hits_;
    order_.splice(order_.begin(), order_, it->second);
    return it->second->value;
  }

  /// Stores `value` of `bytes` bytes, evicting the least recently used entries to stay within the
  /// capacity. A value larger than the whole capacity is not stored (returns false).
  bool put(const std::string& key, std::shared_ptr<const Value> value, std::size_t bytes) {
    std::lock_guard lock(mutex_);
    if (bytes > capacity_) return false;
    if (auto it = index_.find(key); it != index_.end()) erase(it->second);
    while (bytes_ + bytes > capacity_ && !order_.empty()) {
      erase(std::prev(order_.end()));
      ++evictions_;
    }
    order_.push_front({key, std::move(value), bytes});
    index_[key] = order_.begin();
    bytes_ += bytes;
    return true;
  }

  CacheStats stats() const {
    std::lock_guard lock(mutex_);
    return {order_.size(), bytes_, capacity_, hits_, misses_, evictions_};
  }

 private:
  struct Entry {
    std::string key;
    std::shared_ptr<const Value> value;
    std::size_t bytes;
  };
  using Iterator = typename std::list<Entry>::iterator;

  void erase(Iterator it) {
    bytes_ -= it->bytes;
    index_.erase(it->key);
    order_.erase(it);
  }

  mutable std::mutex mutex_;
  std::size_t capacity_;
  std::size_t bytes_ = 0, hits_ = 0, misses_ = 0, evictions_ = 0;
  std::list<Entry> order_;  // most recent first
  std::unordered_map<std::string, Iterator> index_;
};

}  // namespace softtune::render
