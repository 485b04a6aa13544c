#include "softtune/support/lru_cache.h"

#include <gtest/gtest.h>

#include <string>
#include <thread>
#include <vector>

namespace softtune::support {
namespace {

using Cache = LruCache<std::string, int>;

std::shared_ptr<const int> value(int v) { return std::make_shared<const int>(v); }

LruBounds bytes_only(std::size_t max_bytes) { return {.max_bytes = max_bytes}; }

// Bounded by bytes (the preview cache's way).

TEST(LruCache, EvictsTheLeastRecentlyUsedToStayWithinBytes) {
  Cache c(bytes_only(100));
  c.put("a", value(1), 40);
  c.put("b", value(2), 40);
  ASSERT_TRUE(c.get("a"));  // a is now the most recent
  c.put("c", value(3), 40);  // 120 > 100: b goes
  EXPECT_FALSE(c.get("b"));
  EXPECT_EQ(*c.get("a"), 1);
  EXPECT_EQ(*c.get("c"), 3);
  const LruStats s = c.stats();
  EXPECT_EQ(s.entries, 2u);
  EXPECT_EQ(s.bytes, 80u);
  EXPECT_EQ(s.evictions, 1u);
  EXPECT_EQ(s.misses, 1u);
  EXPECT_EQ(s.hits, 3u);
}

TEST(LruCache, ReplacingAKeyReplacesItsBytes) {
  Cache c(bytes_only(100));
  c.put("a", value(1), 60);
  c.put("a", value(2), 30);
  EXPECT_EQ(*c.get("a"), 2);
  EXPECT_EQ(c.stats().bytes, 30u);
  EXPECT_EQ(c.stats().entries, 1u);
  EXPECT_EQ(c.stats().evictions, 0u);  // a replacement is not an eviction
}

TEST(LruCache, AValueLargerThanTheCapacityIsNotStored) {
  Cache c(bytes_only(100));
  c.put("a", value(1), 50);
  EXPECT_FALSE(c.put("huge", value(2), 101));
  EXPECT_FALSE(c.get("huge"));
  EXPECT_TRUE(c.get("a"));  // and nothing was evicted for it
}

TEST(LruCache, AReaderKeepsItsValueAfterEviction) {
  Cache c(bytes_only(10));
  c.put("a", value(7), 10);
  auto held = c.get("a");
  c.put("b", value(8), 10);
  EXPECT_FALSE(c.get("a"));
  EXPECT_EQ(*held, 7);
}

// Bounded by entries and bytes (the response cache's way).

TEST(LruCache, EvictsTheLeastRecentlyUsedToStayWithinEntries) {
  Cache c({.max_entries = 2, .max_bytes = 1 << 20});
  c.put("a", value(1), 1);
  c.put("b", value(2), 1);
  ASSERT_TRUE(c.get("a"));  // "b" is now the least recently used
  c.put("c", value(3), 1);
  EXPECT_EQ(c.stats().entries, 2u);
  EXPECT_EQ(*c.get("a"), 1);
  EXPECT_EQ(c.get("b"), nullptr);
  EXPECT_EQ(*c.get("c"), 3);
  EXPECT_EQ(c.stats().evictions, 1u);
}

TEST(LruCache, WhicheverBoundIsReachedFirstEvicts) {
  Cache c({.max_entries = 100, .max_bytes = 40});
  for (int i = 1; i <= 5; ++i) c.put(std::to_string(i), value(i), 10);  // the fifth makes 50 bytes
  EXPECT_EQ(c.stats().entries, 4u);
  EXPECT_LE(c.stats().bytes, 40u);
  EXPECT_EQ(c.get("1"), nullptr);
  EXPECT_TRUE(c.get("5"));
}

TEST(LruCache, NoEntriesAllowedStoresNothing) {
  Cache c({.max_entries = 0});
  EXPECT_FALSE(c.put("a", value(1), 1));
  EXPECT_EQ(c.get("a"), nullptr);
  EXPECT_EQ(c.stats().entries, 0u);
}

TEST(LruCache, ConcurrentUseKeepsTheBound) {
  Cache c(bytes_only(1000));
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([&c, t] {
      for (int i = 0; i < 2000; ++i) {
        const std::string key = std::to_string((i * 7 + t) % 50);
        if (i % 3 == 0) {
          c.put(key, value(i), 10 + i % 40);
        } else {
          c.get(key);
        }
      }
    });
  }
  for (auto& t : threads) t.join();
  EXPECT_LE(c.stats().bytes, 1000u);
}

}  // namespace
}  // namespace softtune::support
