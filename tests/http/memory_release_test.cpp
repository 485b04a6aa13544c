#include "http/memory_release.h"

#include <gtest/gtest.h>

#include <atomic>
#include <thread>
#include <vector>

#include "http/routes.h"
#include "http/service.h"
#include "softtune/support/sanitizer_build.h"

using softtune::http::HttpRequest;
using softtune::http::Service;

namespace {

HttpRequest post(std::string path, std::string body) {
  HttpRequest r;
  r.method = "POST";
  r.path = std::move(path);
  r.headers.emplace("Content-Type", "application/json");
  r.body = std::move(body);
  return r;
}

HttpRequest get(std::string path) {
  HttpRequest r;
  r.method = "GET";
  r.path = std::move(path);
  return r;
}

// A stability sweep of 3600 listed cases: a JSON tree of about 10 MB, the kind of request that left the
// server holding hundreds of MB.
std::string sweep(int i) {
  return R"({"steps": [0.001, 0.01, 0.1], "masses": [1, 10, 100],
             "damping_ratios": [0, 0.1, 1, 10], "frequency_ratios": [0.01, 0.1, 0.3, 1, 2],
             "chain": false, "observe_steps": )" +
         std::to_string(1000 + i) + "}";
}

// One of a fuzz-like mix: large sweeps, tunes, refused and malformed bodies, scenes, unknown paths.
HttpRequest mixed(int i) {
  switch (i % 8) {
    case 0:
    case 4: return post("/api/v1/stability", sweep(i));
    case 1: return post("/api/v1/tune", R"({"frequency_hz": )" + std::to_string(1 + i % 50) + R"(, "damping_ratio": 0.5, "effective_mass": 2})");
    case 2: return post("/api/v1/stability", R"({"observe_steps": 99999})");  // over the budget
    case 3: return post("/api/v1/tune", std::string(20000, '[') + "1");      // too deep
    case 6: return post("/api/v1/simulate", R"({"preset": "oscillator"})");
    case 5: return post("/api/v1/accuracy", R"({"frequency_hz": 10, "oscillation": "free", "effective_mass": 1, "box2d": false})");
    case 7: return get("/api/v1/presets/" + std::string(300, 'x'));
    default: return post("/api/v1/tune", R"({"frequency_hz": 1e309, "damping_ratio": 0.5, "effective_mass": 2})");
  }
}

}  // namespace

TEST(MemoryRelease, TrimsAfterLargeRequestsOnly) {
  softtune::http::MemoryRelease m;
  m.enter();
  EXPECT_FALSE(m.leave(std::chrono::milliseconds(1), 100));
  m.enter();
  EXPECT_TRUE(m.leave(softtune::http::kTrimAfterRequestTime, 100));
  m.enter();
  EXPECT_TRUE(m.leave(std::chrono::milliseconds(1), softtune::http::kTrimAfterBodyBytes));
  // A large request that ends while another is in flight trims; the last one to leave trims again.
  m.enter();
  m.enter();
  EXPECT_TRUE(m.leave(softtune::http::kTrimAfterRequestTime, 0));
  EXPECT_TRUE(m.leave(std::chrono::milliseconds(1), 0));
  m.enter();
  EXPECT_FALSE(m.leave(std::chrono::milliseconds(1), 0));
  EXPECT_EQ(m.trims(), 4u);
}


// After a warm-up (one request of each kind), eight threads send a mixed sequence; when they are done
// the resident set must be back within twice its warmed-up size. Without the trims it ended at 46 MB
// after a 15 MB warm-up (with them: 12 MB). ASan's allocator keeps freed memory in quarantine on purpose.
TEST(MemoryRelease, ResidentSetReturnsAfterAMixedConcurrentSequence) {
#if SOFTTUNE_SANITIZED_BUILD
  GTEST_SKIP() << "sanitizer allocators keep freed memory";
#else
  softtune::http::ServiceConfig config;
  config.presets_dir = SOFTTUNE_SOURCE_DIR "/presets";
  Service service(config, softtune::http::service_routes());
  for (int i = 0; i < 8; ++i) ASSERT_LT(service.handle(mixed(i)).status, 500) << i;
  ASSERT_EQ(service.handle(mixed(0)).status, 200);
  const std::size_t warm = softtune::http::resident_bytes();
  ASSERT_GT(warm, 0u);
  constexpr int kThreads = 8, kPerThread = 4;
  std::atomic<int> errors{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t) {
    threads.emplace_back([&, t] {
      for (int i = 0; i < kPerThread; ++i) {
        if (service.handle(mixed(t * kPerThread + i)).status >= 500) ++errors;
      }
    });
  }
  for (std::thread& t : threads) t.join();
  const std::size_t after = softtune::http::resident_bytes();
  EXPECT_EQ(errors.load(), 0);
  EXPECT_LT(after, 2 * warm) << "warm " << warm / 1024 << " KiB, after " << after / 1024 << " KiB";
  EXPECT_GT(service.memory_release().trims(), 0u);
#endif
}
