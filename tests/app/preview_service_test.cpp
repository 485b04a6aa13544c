// PreviewService (server/codec/preview_service.cpp): how many requests may wait for frames at once.
#include "app/preview_service.h"

#include <gtest/gtest.h>

#include <chrono>
#include <condition_variable>
#include <future>
#include <mutex>
#include <stdexcept>

#include "codec/problem.h"

namespace softtune::codec {
namespace {

using namespace softtune::app;

using nlohmann::json;

// A renderer that holds every frame until the test opens the gate.
struct Gate {
  std::mutex m;
  std::condition_variable cv;
  bool open = false;
  void release() {
    std::lock_guard lock(m);
    open = true;
    cv.notify_all();
  }
  void pass() {
    std::unique_lock lock(m);
    cv.wait(lock, [this] { return open; });
  }
};

class GatedRenderer final : public render::Renderer {
 public:
  explicit GatedRenderer(Gate& gate) : gate_(gate) {}
  void render(const render::DrawFrame&, const render::Camera&, render::ImageSize, std::span<std::uint8_t> rgba) override {
    gate_.pass();
    std::fill(rgba.begin(), rgba.end(), std::uint8_t{255});
  }

 private:
  Gate& gate_;
};

json oscillator(int response_frames) {
  return {{"response_frames", response_frames}, {"oscillation", "some"}, {"effective_mass", 1},
          {"frames", 2}, {"size", "32x18"}};
}

bool has_warning(const json& answer, const std::string& code) {
  for (const json& w : answer["warnings"]) {
    if (w["code"] == code) return true;
  }
  return false;
}

TEST(PreviewService, PastTheWaiterCapARequestIsAnsweredAtOnceAndStillRendered) {
  Gate gate;
  render::PipelineOptions options;
  options.make_renderer = [&gate] { return std::make_unique<GatedRenderer>(gate); };
  PreviewService service(options, 1);

  // The first request waits (its frames are held at the gate) ...
  auto first = std::async(std::launch::async, [&] { return service.start(oscillator(12), "", "/p"); });
  ASSERT_EQ(first.wait_for(std::chrono::milliseconds(200)), std::future_status::timeout);
  // ... so the second may not: it is answered at once with a progress URL and says why.
  auto declined = std::async(std::launch::async, [&] { return service.start(oscillator(13), "", "/p"); });
  if (declined.wait_for(std::chrono::seconds(5)) != std::future_status::ready) {
    ADD_FAILURE() << "the second request waited for its frames too";
    gate.release();
  }
  const json second = declined.get();
  EXPECT_EQ(second["status"], "rendering");
  EXPECT_TRUE(has_warning(second, "wait_declined")) << second.dump();

  gate.release();
  const json done = first.get();
  EXPECT_EQ(done["status"], "done");
  EXPECT_FALSE(has_warning(done, "wait_declined"));
  // The declined request's render went on; asking again waits for it or finds it done.
  const json again = service.start(oscillator(13), "", "/p");
  EXPECT_EQ(again["status"], "done");
  EXPECT_EQ(again["id"], second["id"]);
  EXPECT_FALSE(has_warning(again, "wait_declined"));
}

// Whether the frames fail while the request waits or before it looks, the answer is the same problem.
TEST(PreviewService, FailedFramesAreARenderFailedProblem) {
  struct Failing final : public render::Renderer {
    void render(const render::DrawFrame&, const render::Camera&, render::ImageSize, std::span<std::uint8_t>) override {
      throw std::runtime_error("injected GL fault");
    }
  };
  render::PipelineOptions options;
  options.make_renderer = [] { return std::make_unique<Failing>(); };
  PreviewService service(options);
  for (int attempt = 0; attempt < 100; ++attempt) {
    try {
      service.start(oscillator(12 + attempt), "", "/p");
      ADD_FAILURE() << "a failed preview was answered";
    } catch (const Problem& p) {
      EXPECT_EQ(p.status, 500);
      EXPECT_EQ(p.title, "Render failed");
      EXPECT_NE(p.detail.find("injected GL fault"), std::string::npos) << p.detail;
    }
  }
}

}  // namespace
}  // namespace softtune::codec
