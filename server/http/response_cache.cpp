#include "http/response_cache.h"

namespace softtune::http {

ResponseCache::ResponseCache(std::size_t max_entries, std::size_t max_bytes)
    : max_entries_(max_entries), max_bytes_(max_bytes) {}

std::shared_ptr<const std::string> ResponseCache::find(const std::string& key) {
  const std::lock_guard lock(mutex_);
  auto it = index_.find(key);
  if (it == index_.end()) return nullptr;
  order_.splice(order_.begin(), order_, it->second);
  return it->second->body;
}

void ResponseCache::insert(const std::string& key, std::shared_ptr<const std::string> body) {
  const std::size_t size = key.size() + body->size();
  if (max_entries_ == 0 || size > max_bytes_ / 4) return;
  const std::lock_guard lock(mutex_);
  if (auto it = index_.find(key); it != index_.end()) {
    bytes_ -= it->second->key.size() + it->second->body->size();
    order_.erase(it->second);
    index_.erase(it);
  }
  order_.push_front(Entry{key, std::move(body)});
  index_[key] = order_.begin();
  bytes_ += size;
  evict_locked();
}

void ResponseCache::evict_locked() {
  while (!order_.empty() && (order_.size() > max_entries_ || bytes_ > max_bytes_)) {
    const Entry& last = order_.back();
    bytes_ -= last.key.size() + last.body->size();
    index_.erase(last.key);
    order_.pop_back();
  }
}

std::size_t ResponseCache::entries() const {
  const std::lock_guard lock(mutex_);
  return order_.size();
}

std::size_t ResponseCache::bytes() const {
  const std::lock_guard lock(mutex_);
  return bytes_;
}

}  // namespace softtune::http
