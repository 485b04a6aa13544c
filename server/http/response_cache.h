#pragma once
// A bounded LRU cache of response bodies for deterministic JSON contracts (tune gives the same bytes
// for the same request), keyed by the contract and the canonical request (routes.cpp: sorted keys, numbers
// as doubles), so {"a":1,"b":2} and { "b": 2, "a": 1.0 } share an entry; routes.cpp also stores each
// spelling's raw bytes as a key to the same body, so a repeat is found without parsing. Thread-safe.
// The LRU itself is support::LruCache (core/include/softtune/support/lru_cache.h); this adds the
// weighing (key plus body bytes) and the rule that keeps one body from flushing the cache.

#include <cstddef>
#include <memory>
#include <string>

#include "softtune/support/lru_cache.h"

namespace softtune::http {

class ResponseCache {
 public:
  ResponseCache(std::size_t max_entries, std::size_t max_bytes);

  /// The cached body, or nullptr. A hit makes the entry the most recently used.
  std::shared_ptr<const std::string> find(const std::string& key);
  /// Stores a body, evicting the least recently used entries past either bound. Bodies larger than
  /// a quarter of max_bytes are not stored.
  void insert(const std::string& key, std::shared_ptr<const std::string> body);

  std::size_t entries() const;
  std::size_t bytes() const;  ///< keys plus bodies

 private:
  support::LruCache<std::string, std::string> lru_;
};

}  // namespace softtune::http
