#pragma once
// The one least-recently-used cache of the project, used by both of its caches: preview results
// (render/frame_pipeline.h, bounded by bytes: PipelineOptions::cache_bytes) and tune response bodies
// (server/http/response_cache.h, bounded by limits::kResponseCacheEntries entries and
// limits::kResponseCacheBytes bytes). The caller weighs each value as it stores it (a preview's bytes(),
// a response's key plus body). Values are shared and immutable, so a reader keeps its copy alive after
// eviction. Thread-safe (one mutex). A plain container, no I/O, so it sits beside core and both render/
// and server/ reach it through the header-only target softtune_support without depending on each other.

#include <cstddef>
#include <functional>
#include <limits>
#include <list>
#include <memory>
#include <mutex>
#include <unordered_map>
#include <utility>

namespace softtune::support {

/// Both bounds hold after every put(); the default is unbounded.
struct LruBounds {
  std::size_t max_entries = std::numeric_limits<std::size_t>::max();
  std::size_t max_bytes = std::numeric_limits<std::size_t>::max();  ///< bytes, the sum of the weights
};

struct LruStats {
  std::size_t entries = 0;
  std::size_t bytes = 0;  ///< sum of the entries' weights
  LruBounds bounds;
  std::size_t hits = 0, misses = 0;  ///< get() calls that found / did not find their key
  std::size_t evictions = 0;         ///< entries dropped to make room (not replacements of a key)
};

template <typename Key, typename Value, typename Hash = std::hash<Key>>
class LruCache {
 public:
  explicit LruCache(LruBounds bounds) : bounds_(bounds) {}

  /// The value under `key` (now the most recently used), or nullptr.
  std::shared_ptr<const Value> get(const Key& key) {
    const std::lock_guard lock(mutex_);
    auto it = index_.find(key);
    if (it == index_.end()) {
      ++misses_;
      return nullptr;
    }
    ++hits_;
    order_.splice(order_.begin(), order_, it->second);
    return it->second->value;
  }

  /// Stores `value` weighing `bytes` under `key` (replacing what was there) as the most recently used,
  /// evicting the least recently used entries to stay within both bounds. A value that could not fit
  /// alone is not stored, and nothing is evicted for it (returns false).
  bool put(const Key& key, std::shared_ptr<const Value> value, std::size_t bytes) {
    const std::lock_guard lock(mutex_);
    if (bytes > bounds_.max_bytes || bounds_.max_entries == 0) return false;
    if (auto it = index_.find(key); it != index_.end()) erase(it->second);
    while (!order_.empty() && (bytes_ + bytes > bounds_.max_bytes || order_.size() + 1 > bounds_.max_entries)) {
      erase(std::prev(order_.end()));
      ++evictions_;
    }
    order_.push_front(Entry{key, std::move(value), bytes});
    index_[key] = order_.begin();
    bytes_ += bytes;
    return true;
  }

  const LruBounds& bounds() const { return bounds_; }

  LruStats stats() const {
    const std::lock_guard lock(mutex_);
    return {order_.size(), bytes_, bounds_, hits_, misses_, evictions_};
  }

 private:
  struct Entry {
    Key key;
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
  const LruBounds bounds_;
  std::size_t bytes_ = 0, hits_ = 0, misses_ = 0, evictions_ = 0;
  std::list<Entry> order_;  // most recently used first
  std::unordered_map<Key, Iterator, Hash> index_;
};

}  // namespace softtune::support
