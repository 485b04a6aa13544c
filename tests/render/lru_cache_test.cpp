#include "softtune/render/lru_cache.h"

#include <gtest/gtest.h>

#include <thread>
#include <vector>

namespace softtune::render {
namespace {

std::shared_ptr<const int> value(int v) { return std::make_shared<const int>(v); }

TEST(LruCache, EvictsTheLeastRecentlyUsedToStayWithinBytes) {
  LruCache<int> c(100);
  c.put("a", value(1), 40);
  c.put("b", value(2), 40);
  ASSERT_TRUE(c.get("a"));  // a is now the most recent
  c.put("c", value(3), 40);  // 120 > 100: b goes
  EXPECT_FALSE(c.get("b"));
  EXPECT_EQ(*c.get("a"), 1);
  EXPECT_EQ(*c.get("c"), 3);
  const CacheStats s = c.stats();
  EXPECT_EQ(s.entries, 2u);
  EXPECT_EQ(s.bytes, 80u);
  EXPECT_EQ(s.evictions, 1u);
  EXPECT_EQ(s.misses, 1u);
  EXPECT_EQ(s.hits, 3u);
}

TEST(LruCache, ReplacingAKeyReplacesItsBytes) {
  LruCache<int> c(100);
  c.put("a", value(1), 60);
  c.put("a", value(2), 30);
  EXPECT_EQ(*c.get("a"), 2);
  EXPECT_EQ(c.stats().bytes, 30u);
}

TEST(LruCache, AValueLargerThanTheCapacityIsNotStored) {
  LruCache<int> c(100);
  c.put("a", value(1), 50);
  EXPECT_FALSE(c.put("huge", value(2), 101));
  EXPECT_FALSE(c.get("huge"));
  EXPECT_TRUE(c.get("a"));  // and nothing was evicted for it
}

TEST(LruCache, AReaderKeepsItsValueAfterEviction) {
  LruCache<int> c(10);
  c.put("a", value(7), 10);
  auto held = c.get("a");
  c.put("b", value(8), 10);
  EXPECT_FALSE(c.get("a"));
  EXPECT_EQ(*held, 7);
}

TEST(LruCache, ConcurrentUseKeepsTheBound) {
  LruCache<int> c(1000);
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
}  // namespace softtune::render
