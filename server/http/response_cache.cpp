#include "http/response_cache.h"

namespace softtune::http {

ResponseCache::ResponseCache(std::size_t max_entries, std::size_t max_bytes)
    : lru_(support::LruBounds{max_entries, max_bytes}) {}

std::shared_ptr<const std::string> ResponseCache::find(const std::string& key) { return lru_.get(key); }

void ResponseCache::insert(const std::string& key, std::shared_ptr<const std::string> body) {
  const std::size_t size = key.size() + body->size();
  if (size > lru_.bounds().max_bytes / 4) return;
  lru_.put(key, std::move(body), size);
}

std::size_t ResponseCache::entries() const { return lru_.stats().entries; }

std::size_t ResponseCache::bytes() const { return lru_.stats().bytes; }

}  // namespace softtune::http
