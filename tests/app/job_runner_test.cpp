// The job runner (app/job_runner.cpp) with the jobs it runs: a stability job's result is run_stability's
// answer and a check job's the check report, progress only grows and reaches its total, a cancel stops a
// running sweep at its next case, the queue and the kept results are bounded, and ids have one form.
#include "app/job_runner.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

#include "../codec/stability_sweeps.h"
#include "app/check_request.h"
#include "app/stability_app.h"
#include "codec/problem.h"
#include "codec/stability_codec.h"
#include "softtune/support/run_limit.h"

namespace softtune::app {
namespace {

using nlohmann::json;

// Polls until the job has ended (or 20 s, far above any job here), recording every progress seen.
json wait_until_ended(JobRunner& runner, const std::string& id, std::vector<std::size_t>* seen = nullptr) {
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  for (;;) {
    const json s = json::parse(runner.status(id).value());
    if (seen) seen->push_back(s["progress"]["done"].get<std::size_t>());
    const std::string state = s["state"];
    if (state == "done" || state == "failed" || state == "cancelled") return s;
    if (std::chrono::steady_clock::now() > give_up) return s;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
}

TEST(JobRunner, StabilityJobAnswersTheSynchronousJsonWithMonotoneProgress) {
  JobRunner runner;
  const codec::StabilityRequest q = codec::decode_stability_request(test::small_sweep());
  const auto id = runner.submit([&q](JobProgress& p) { return run_stability_job(q, p); });
  ASSERT_TRUE(id);
  std::vector<std::size_t> seen;
  const json s = wait_until_ended(runner, *id, &seen);
  ASSERT_EQ(s["state"], "done") << s.dump();
  EXPECT_EQ(s["result"], run_stability(q));
  // The total is every case the answer counts: the sweep's and the chain's.
  const std::size_t cases = s["result"]["summary"]["cases"].get<std::size_t>() + s["result"]["chain"]["cases"].get<std::size_t>();
  EXPECT_EQ(s["result"]["cases"].size(), s["result"]["summary"]["cases"]);
  EXPECT_EQ(s["progress"]["total"], cases);
  EXPECT_EQ(s["progress"]["done"], cases);
  EXPECT_DOUBLE_EQ(s["progress"]["fraction"].get<double>(), 1.0);
  for (std::size_t i = 1; i < seen.size(); ++i) EXPECT_LE(seen[i - 1], seen[i]);
  EXPECT_GE(s["elapsed_s"].get<double>(), 0.0);
}

TEST(JobRunner, CheckJobAnswersTheCheckReport) {
  JobRunner runner;
  const json request = {{"presets", {"mouse"}}, {"fps", {30, 60}}};
  const CheckPlan plan = plan_check_job(request, SOFTTUNE_PRESETS_DIR);
  const auto id = runner.submit([&plan](JobProgress& p) { return run_check_plan(plan, &p).json; });
  ASSERT_TRUE(id);
  const json s = wait_until_ended(runner, *id);
  ASSERT_EQ(s["state"], "done") << s.dump();
  EXPECT_EQ(s["result"], run_check_request(request, SOFTTUNE_PRESETS_DIR).json);
  EXPECT_EQ(s["progress"]["total"], 2);  // one preset at two rates
  EXPECT_EQ(s["progress"]["done"], 2);
}

TEST(JobRunner, CancelStopsARunningSweepAtItsNextCase) {
  JobRunner runner;
  // The default grid at 20000 observed steps: 17500 cases, about 10 s; cancelled after its first cases.
  const codec::StabilityRequest q = codec::decode_stability_request({{"observe_steps", 20000}, {"chain", false}});
  const auto id = runner.submit([&q](JobProgress& p) { return run_stability_job(q, p); });
  ASSERT_TRUE(id);
  while (json::parse(runner.status(*id).value())["progress"]["done"].get<std::size_t>() < 10) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  EXPECT_TRUE(runner.cancel(*id));
  const json s = wait_until_ended(runner, *id);
  EXPECT_EQ(s["state"], "cancelled");
  EXPECT_FALSE(s.contains("result"));
  const std::size_t done = s["progress"]["done"], total = s["progress"]["total"];
  EXPECT_EQ(total, sweep_case_count(q.sweep));
  EXPECT_LT(done, total / 10) << "the sweep went on after the cancel";
}

// Work that never reports progress (one long Box2D run, one long sweep case) still stops within 1 s of a
// cancel: the job runs under a run-time limit (softtune/support/run_limit.h) that carries its cancel flag,
// checked by the long loops (here, this loop) between frames.
TEST(JobRunner, CancelStopsWorkBetweenFramesWithinASecond) {
  JobRunner runner;
  std::atomic<bool> started{false};
  const auto id = runner.submit([&started](JobProgress&) -> json {
    started = true;
    for (;;) support::check_run_limit();
  });
  ASSERT_TRUE(id);
  while (!started) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  const auto cancelled_at = std::chrono::steady_clock::now();
  EXPECT_TRUE(runner.cancel(*id));
  const json s = wait_until_ended(runner, *id);
  EXPECT_EQ(s["state"], "cancelled");
  EXPECT_LT(std::chrono::steady_clock::now() - cancelled_at, std::chrono::seconds(1));
}

TEST(JobRunner, QueueIsBoundedAndAQueuedCancelFreesItsPlace) {
  JobRunner runner(JobLimits{2, 4, std::chrono::seconds(600), kMaxKeptJobBytes});
  // A job that runs until cancelled, one unit a millisecond.
  auto endless = [](JobProgress& p) -> json {
    p.set_total(1000000);
    while (p.advance()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    throw JobCancelled{};
  };
  const auto a = runner.submit(endless), b = runner.submit(endless);
  ASSERT_TRUE(a && b);
  EXPECT_FALSE(runner.submit(endless));
  EXPECT_TRUE(runner.cancel(*b));  // queued behind a: cancelled at once
  EXPECT_EQ(json::parse(runner.status(*b).value())["state"], "cancelled");
  const auto c = runner.submit(endless);
  EXPECT_TRUE(c);
  runner.cancel(*a);
  runner.cancel(*c);
  EXPECT_EQ(wait_until_ended(runner, *a)["state"], "cancelled");
}

TEST(JobRunner, FailuresCarryTheirProblemAndFinishedJobsAreBounded) {
  JobRunner runner(JobLimits{4, 1, std::chrono::seconds(600), kMaxKeptJobBytes});
  const auto bad = runner.submit([](JobProgress&) -> json { throw codec::invalid_field("observe_steps", "must be small"); });
  ASSERT_TRUE(bad);
  const json s = wait_until_ended(runner, *bad);
  EXPECT_EQ(s["state"], "failed");
  EXPECT_EQ(s["problem"]["status"], 422);
  EXPECT_EQ(s["problem"]["field"], "observe_steps");
  const auto good = runner.submit([](JobProgress& p) -> json {
    p.set_total(1);
    p.advance();
    return {{"ok", true}};
  });
  ASSERT_TRUE(good);
  EXPECT_EQ(wait_until_ended(runner, *good)["result"], json({{"ok", true}}));
  EXPECT_FALSE(runner.status(*bad)) << "only one finished job is kept";
}

TEST(JobRunner, KeptResultsAreBoundedInBytes) {
  JobRunner runner(JobLimits{4, 32, std::chrono::seconds(600), 300});
  auto text = [](JobProgress&) -> json { return std::string(200, 'x'); };  // 202 bytes of JSON text
  const auto first = runner.submit(text);
  ASSERT_TRUE(first);
  EXPECT_EQ(json::parse(wait_until_ended(runner, *first).dump())["result"], std::string(200, 'x'));
  const auto second = runner.submit(text);
  ASSERT_TRUE(second);
  EXPECT_EQ(wait_until_ended(runner, *second)["state"], "done");
  EXPECT_FALSE(runner.status(*first)) << "404 bytes kept, over the 300-byte bound: the oldest goes";
  EXPECT_TRUE(runner.status(*second)) << "the newest result is kept whatever its size";
}

TEST(JobRunner, IdsHaveOneForm) {
  JobRunner runner;
  const auto id = runner.submit([](JobProgress&) -> json { return json::object(); });
  ASSERT_TRUE(id);
  EXPECT_TRUE(is_job_id(*id)) << *id;
  EXPECT_EQ(id->size(), kJobIdLength);
  for (const char* bad : {"", "j", "j0123456789abcdeF", "k0123456789abcdef", "j0123456789abcdef0", "J0123456789abcdef"}) {
    EXPECT_FALSE(is_job_id(bad)) << bad;
  }
  EXPECT_FALSE(runner.status("j0123456789abcdef") && *id != "j0123456789abcdef");
  EXPECT_FALSE(runner.cancel(*id == "j0000000000000000" ? "j0000000000000001" : "j0000000000000000"));
}

}  // namespace
}  // namespace softtune::app
